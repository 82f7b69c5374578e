#include "eval/compare.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "core/error.h"
#include "eval/metrics/metrics_json.h"
#include "io/trajectory_io.h"

namespace slamkit::eval {
namespace {

using nlohmann::json;

struct Column {
  const char* header;
  const char* section;  // "ate" or "rpe"
  const char* key;      // "rmse", or "trans.rmse" style for nested values
};

const Column kColumns[] = {
    {"ATE pairs", "ate", "pairs"},
    {"ATE rmse [m]", "ate", "rmse"},
    {"ATE mean [m]", "ate", "mean"},
    {"ATE median [m]", "ate", "median"},
    {"ATE std [m]", "ate", "std"},
    {"ATE min [m]", "ate", "min"},
    {"ATE max [m]", "ate", "max"},
    {"ATE rot rmse [deg]", "ate", "rot_deg.rmse"},
    {"RPE pairs", "rpe", "pairs"},
    {"RPE trans rmse [m]", "rpe", "trans.rmse"},
    {"RPE rot rmse [deg]", "rpe", "rot_deg.rmse"},
};

// The cell text: integers as is, metres/degrees to 6 decimals (the benchmark's digits).
std::string cell(const EvaluatedRun& run, const Column& c) {
  const json* x = metric_value(run, std::string(c.section) + "." + c.key);
  if (!x) return "";
  if (!x->is_number() || !std::isfinite(x->get<double>()))
    throw_input_error((run.dir / "metrics.json").string(),
                      std::string(c.section) + "." + c.key + " is " + printable(x->dump()) +
                          ", not a finite number (written from overflowing input by an older "
                          "slamkit? evaluate the run again)");
  if (x->is_number_integer()) return std::to_string(x->get<long long>());
  char text[32];
  std::snprintf(text, sizeof text, "%.6f", x->get<double>());
  return text;
}

std::ofstream open_output(const std::filesystem::path& path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw_input_error(path.string(), "cannot write file");
  return out;
}

}  // namespace

const json* metric_value(const EvaluatedRun& run, const std::string& path) {
  const json* v = &run.metrics;
  std::string key = path;
  for (size_t dot; (dot = key.find('.')) != std::string::npos; key = key.substr(dot + 1)) {
    if (!v->is_object() || !v->contains(key.substr(0, dot))) return nullptr;
    v = &(*v)[key.substr(0, dot)];
  }
  return v->is_object() && v->contains(key) ? &(*v)[key] : nullptr;
}

std::vector<EvaluatedRun> load_runs(const std::vector<std::filesystem::path>& dirs) {
  std::vector<EvaluatedRun> runs;
  std::set<std::string> names;
  for (const auto& dir : dirs) {
    EvaluatedRun run;
    run.dir = dir;
    require_complete_run(dir);
    run.metrics = read_metrics_file(dir / "metrics.json");
    if (!run.metrics.contains("ate") || !run.metrics["ate"].is_object())
      throw_input_error((dir / "metrics.json").string(),
                        "no \"ate\" section: run `slamkit eval ate` for this run first");
    const json settings = run.metrics.contains("settings") && run.metrics["settings"].is_object()
                              ? run.metrics["settings"]
                              : json::object();
    const json name = settings.value("system_name", json());
    // Names are printed with the table: escape control characters from the file.
    run.name = name.is_string() ? printable(name.get<std::string>(), 200) : "";
    if (run.name.empty()) run.name = std::filesystem::absolute(dir).lexically_normal().filename();
    if (run.name.empty()) run.name = dir.string();
    if (names.count(run.name)) run.name += " (" + dir.string() + ")";
    names.insert(run.name);
    const json title = settings.value("title", json());
    run.sequence = title.is_string() ? printable(title.get<std::string>(), 200) : "";
    for (const Column& c : kColumns) cell(run, c);  // a bad value fails before any output
    runs.push_back(std::move(run));
  }
  return runs;
}

void write_comparison_markdown(const std::filesystem::path& path,
                               const std::vector<EvaluatedRun>& runs) {
  std::ofstream out = open_output(path);
  out << "| run | sequence |";
  for (const Column& c : kColumns) out << " " << c.header << " |";
  out << "\n|---|---|";
  for (size_t k = 0; k < std::size(kColumns); ++k) out << "---:|";
  out << "\n";
  for (const EvaluatedRun& run : runs) {
    out << "| " << run.name << " | " << run.sequence << " |";
    for (const Column& c : kColumns) out << " " << cell(run, c) << " |";
    out << "\n";
  }
}

void write_comparison_csv(const std::filesystem::path& path,
                          const std::vector<EvaluatedRun>& runs) {
  std::ofstream out = open_output(path);
  // Names may hold commas; quote them as CSV requires.
  const auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
  };
  out << "run,sequence,dir";
  for (const Column& c : kColumns) out << "," << quoted(c.header);
  out << "\n";
  for (const EvaluatedRun& run : runs) {
    out << quoted(run.name) << "," << quoted(run.sequence) << "," << quoted(run.dir.string());
    for (const Column& c : kColumns) out << "," << cell(run, c);
    out << "\n";
  }
}

}  // namespace slamkit::eval
