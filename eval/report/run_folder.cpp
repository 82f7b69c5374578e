#include "eval/report/run_folder.h"

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "eval/loop_accuracy.h"
#include "eval/metrics/metrics_json.h"
#include "io/line_reader.h"
#include "io/path_kind.h"
#include "io/trajectory_io.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

bool is_file(const fs::path& path) { return path_kind(path) == PathKind::kFile; }

std::string read_whole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error(path.string(), "cannot read file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

json read_json_object(const fs::path& path) {
  const json j = json::parse(read_whole(path), nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw_input_error(path.string(), "not a JSON object");
  return j;
}

// The comma-separated tables slamkit writes (tracking.csv, loop_check.csv): a header, then rows
// of exactly as many fields; no quoting, since none of their fields holds a comma.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::pair<int, std::vector<std::string>>> rows;  // line number, fields

  size_t column(const fs::path& path, const std::string& name) const {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    throw_input_error(path.string(), 1, "no column '" + name + "' in the header");
  }
};

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

CsvTable read_csv(const fs::path& path) {
  LineReader reader(path, path.string());
  CsvTable table;
  std::string_view view;
  while (reader.next(view)) {
    const int number = reader.line_number();
    std::string line(view);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      table.header = split_commas(line);
      continue;
    }
    if (line.empty()) continue;
    std::vector<std::string> fields = split_commas(line);
    if (fields.size() != table.header.size())
      throw_input_error(path.string(), number,
                        std::to_string(fields.size()) + " fields where the header names " +
                            std::to_string(table.header.size()));
    table.rows.emplace_back(number, std::move(fields));
  }
  if (table.header.empty()) throw_input_error(path.string(), "empty: no header line");
  return table;
}

double parse_field(const fs::path& path, int line, const std::string& text) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw_input_error(path.string(), line, "'" + printable(text) + "' is not a number");
  return value;
}

// tracking.csv's columns that hold words rather than numbers.
bool is_text_column(const std::string& name) { return name == "solver" || name == "failure"; }

void read_tracking_csv(const fs::path& path, RunFolder& run) {
  const CsvTable table = read_csv(path);
  const size_t stamp = table.column(path, "stamp");
  const size_t lost = table.column(path, "lost");
  for (size_t c = 0; c < table.header.size(); ++c) {
    if (is_text_column(table.header[c])) continue;
    std::vector<double>& values = run.frames[table.header[c]];
    values.reserve(table.rows.size());
    for (const auto& [line, fields] : table.rows)
      values.push_back(parse_field(path, line, fields[c]));
  }
  for (const auto& [line, fields] : table.rows)
    if (parse_field(path, line, fields[lost]) != 0)
      run.lost_stamps.push_back(parse_field(path, line, fields[stamp]));
}

PoseErrors read_errors_csv(const fs::path& path) {
  const CsvTable table = read_csv(path);
  const char* names[] = {"time", "ate_m", "est_tx", "est_ty", "est_tz", "gt_tx", "gt_ty", "gt_tz"};
  size_t at[8];
  for (int i = 0; i < 8; ++i) at[i] = table.column(path, names[i]);
  PoseErrors errors;
  for (const auto& [line, fields] : table.rows) {
    double v[8];
    for (int i = 0; i < 8; ++i) v[i] = parse_field(path, line, fields[at[i]]);
    errors.stamps.push_back(v[0]);
    errors.ate_m.push_back(v[1]);
    errors.estimate.emplace_back(v[2], v[3], v[4]);
    errors.groundtruth.emplace_back(v[5], v[6], v[7]);
  }
  return errors;
}

// metrics.json's ATE alignment, x -> s R x + t.
std::optional<Eigen::Affine3d> read_alignment(const json& metrics) {
  const json* alignment = nullptr;
  if (metrics.contains("ate") && metrics["ate"].contains("alignment"))
    alignment = &metrics["ate"]["alignment"];
  if (!alignment) return std::nullopt;
  const json& a = *alignment;
  if (!a.contains("rotation") || !a.contains("translation")) return std::nullopt;
  Eigen::Matrix3d rotation;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) rotation(r, c) = a["rotation"].at(r).at(c).get<double>();
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  transform.linear() = a.value("scale", 1.0) * rotation;
  for (int d = 0; d < 3; ++d) transform.translation()[d] = a["translation"].at(d).get<double>();
  return transform;
}

void read_loops(const fs::path& dir, RunFolder& run) {
  const fs::path check = dir / "loop_check.csv";
  if (is_file(check)) {
    const CsvTable table = read_csv(check);
    const size_t keyframe = table.column(check, "keyframe_stamp");
    const size_t loop = table.column(check, "loop_stamp");
    const size_t verdict = table.column(check, "verdict");
    for (const auto& [line, fields] : table.rows)
      run.loops.push_back({parse_field(check, line, fields[keyframe]),
                           parse_field(check, line, fields[loop]), fields[verdict]});
    return;
  }
  if (!is_file(dir / "loops.csv")) return;
  for (const AcceptedLoop& loop : read_accepted_loops(dir / "loops.csv"))
    run.loops.push_back({loop.stamp, loop.loop_stamp, "unjudged"});
}

void read_figures(const fs::path& dir, RunFolder& run) {
  for (const char* stem : {"trajectory_xy", "ate_over_time", "rpe_over_time"}) {
    const fs::path svg = dir / (std::string(stem) + ".svg");
    if (is_file(svg)) run.figures[stem] = read_whole(svg);
  }
}

}  // namespace

RunFolder read_run_folder(const fs::path& dir) {
  if (path_kind(dir) != PathKind::kFolder) throw_input_error(dir.string(), "no run folder here");
  RunFolder run;
  run.dir = dir;
  run.name = fs::absolute(dir).lexically_normal().filename().string();
  if (run.name.empty())  // "runs/desk/" normalises to a trailing empty name
    run.name = fs::absolute(dir).lexically_normal().parent_path().filename().string();
  const bool has_run_json = is_file(dir / "run.json");
  if (!has_run_json && !is_file(dir / "trajectory.txt"))
    throw_input_error(dir.string(),
                      "not a run folder: neither run.json nor trajectory.txt (write one with "
                      "`slamkit run` or `slamkit track`)");
  if (has_run_json) {
    run.run = read_json_object(dir / "run.json");
    run.status = run.run.value("status", "unknown");
    if (run.status != "complete") {
      std::string note = "the run is not complete (run.json says '" + run.status + "'";
      if (run.run.contains("error") && run.run["error"].is_string())
        note += ": " + run.run["error"].get<std::string>();
      run.notes.push_back(note + "): this page shows what its folder holds");
    }
  } else {
    run.status = "no run.json";
    run.notes.push_back("no run.json: not written by `slamkit run` or `track`");
  }
  const auto note_missing = [&](const char* file, const char* consequence) {
    run.notes.push_back(std::string("no ") + file + ": " + consequence);
  };
  if (is_file(dir / "metrics.json")) {
    run.metrics = read_metrics_file(dir / "metrics.json");
    if (const auto alignment = read_alignment(run.metrics)) run.to_groundtruth = *alignment;
  } else {
    note_missing("metrics.json",
                 "no groundtruth evaluation (a sequence without groundtruth, or "
                 "--no-eval)");
  }
  if (is_file(dir / "timing.json")) run.timing = read_json_object(dir / "timing.json");
  if (is_file(dir / "settings.yaml")) run.settings_yaml = read_whole(dir / "settings.yaml");
  if (is_file(dir / "trajectory.txt")) {
    run.trajectory = read_tum_trajectory(dir / "trajectory.txt").trajectory;
  } else {
    note_missing("trajectory.txt", "no trajectory");
  }
  if (is_file(dir / "keyframes.txt"))
    run.keyframes = read_tum_trajectory(dir / "keyframes.txt").trajectory;
  if (is_file(dir / "errors.csv")) run.errors = read_errors_csv(dir / "errors.csv");
  if (is_file(dir / "tracking.csv")) {
    read_tracking_csv(dir / "tracking.csv", run);
  } else {
    note_missing("tracking.csv", "no per-frame diagnostics");
  }
  read_loops(dir, run);
  read_figures(dir, run);
  if (is_file(dir / "map.ply")) {
    run.map = dir / "map.ply";
  } else {
    note_missing("map.ply", "no map (`slamkit track` makes none; `run` with map.enabled)");
  }
  // No note without a mesh: only a TSDF map with map.mesh makes one.
  if (is_file(dir / "mesh.ply")) run.mesh = dir / "mesh.ply";
  return run;
}

}  // namespace slamkit::eval
