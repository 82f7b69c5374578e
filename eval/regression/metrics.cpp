#include "eval/regression/metrics.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "eval/metrics/metrics_json.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Where each metric lives in metrics.json or timing.json.
struct JsonSource {
  const char* key;
  const char* pointer;
};
const JsonSource kMetricsJson[] = {
    {"ate_rmse", "/ate/rmse"},
    {"ate_median", "/ate/median"},
    {"ate_max", "/ate/max"},
    {"rpe_trans_rmse", "/rpe/trans/rmse"},
    {"rpe_rot_rmse", "/rpe/rot_deg/rmse"},
    {"map_accuracy_median", "/map/accuracy/median"},
    {"map_accuracy_p95", "/map/accuracy/p95"},
    {"map_completeness", "/map/completeness"},
};
const JsonSource kTimingJson[] = {
    {"run_seconds", "/seconds/total"},
    {"frames_per_second", "/frames_per_second"},
};

template <size_t N>
void take_numbers(const fs::path& file, const json& doc, const JsonSource (&sources)[N],
                  RunMetrics& out) {
  for (const JsonSource& s : sources) {
    const json::json_pointer pointer(s.pointer);
    if (!doc.contains(pointer)) continue;
    const json& v = doc.at(pointer);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw_input_error(file.string(),
                        std::string(s.pointer + 1) + " is " + v.dump() + ", not a finite number");
    out[s.key] = v.get<double>();
  }
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw_input_error(file.string(), "cannot read file");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw_input_error(file.string(), std::string("not valid JSON: ") + e.what());
  }
}

// Frames whose `lost` column is 1.
int count_lost_frames(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw_input_error(file.string(), "cannot read file");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  size_t column = 0;
  while (column < header.size() && header[column] != "lost") ++column;
  if (column == header.size()) throw_input_error(file.string(), 1, "no 'lost' column");
  int lost = 0, number = 1;
  while (std::getline(in, line)) {
    ++number;
    std::stringstream fields(line);
    std::string field;
    for (size_t k = 0; k <= column; ++k)
      if (!std::getline(fields, field, ','))
        throw_input_error(file.string(), number, "fewer fields than the header");
    if (field != "0" && field != "1")
      throw_input_error(file.string(), number, "lost is '" + field + "', not 0 or 1");
    lost += field == "1";
  }
  return lost;
}

}  // namespace

const std::vector<MetricInfo>& tracked_metrics() {
  // Default tolerances sit well above the run-to-run spread of one build on different
  // machines (the engine is deterministic on one machine) and below what a real loss of
  // accuracy moves: 200 instead of 1000 ORB features raises synthetic ATE by 30-200%.
  static const std::vector<MetricInfo> metrics = {
      {"ate_rmse", "ATE RMSE", "m", false, false, {0.0003, 0.10}},
      {"ate_median", "ATE median", "m", false, false, {0.0003, 0.10}},
      {"ate_max", "ATE max", "m", false, false, {0.001, 0.20}},
      {"rpe_trans_rmse", "RPE trans RMSE", "m", false, false, {0.0005, 0.10}},
      {"rpe_rot_rmse", "RPE rot RMSE", "deg", false, false, {0.02, 0.10}},
      {"frames_lost", "frames lost", "frames", false, false, {0, 0}},
      {"map_accuracy_median", "map accuracy median", "m", false, false, {0.0005, 0.10}},
      {"map_accuracy_p95", "map accuracy p95", "m", false, false, {0.001, 0.15}},
      {"map_completeness", "map completeness", "", true, false, {0.02, 0}},
      {"run_seconds", "run time", "s", false, true, {1.0, 0.5}},
      {"frames_per_second", "frames/s", "frames/s", true, true, {0, 0.33}},
  };
  return metrics;
}

const MetricInfo* find_metric(const std::string& key) {
  for (const MetricInfo& m : tracked_metrics())
    if (m.key == key) return &m;
  return nullptr;
}

RunMetrics read_run_metrics(const fs::path& run_dir) {
  eval::require_complete_run(run_dir);
  RunMetrics out;
  if (fs::exists(run_dir / "metrics.json")) {
    const fs::path file = run_dir / "metrics.json";
    take_numbers(file, eval::read_metrics_file(file), kMetricsJson, out);
  }
  if (fs::exists(run_dir / "tracking.csv"))
    out["frames_lost"] = count_lost_frames(run_dir / "tracking.csv");
  if (fs::exists(run_dir / "timing.json")) {
    const fs::path file = run_dir / "timing.json";
    take_numbers(file, read_json(file), kTimingJson, out);
  }
  return out;
}

}  // namespace slamkit::regress
