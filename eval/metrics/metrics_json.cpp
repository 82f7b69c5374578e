#include "eval/metrics/metrics_json.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>

#include "core/error.h"
#include "eval/metrics/checksum.h"
#include "io/path_kind.h"

namespace slamkit::eval {

using nlohmann::json;

json stats_json(const ErrorStats& s) {
  return {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
          {"std", s.std},   {"min", s.min},   {"max", s.max}};
}

std::string rotation_withheld_reason(const Alignment& a) {
  char text[256];
  std::snprintf(text, sizeof text,
                "the matched positions fix the alignment's rotation only to within %.1f deg "
                "(nearly collinear or too short a motion; limit %.1f deg)",
                a.rotation_ambiguity_deg, kMaxRotationAmbiguityDeg);
  return text;
}

json ate_json(const AteResult& ate) {
  json j = stats_json(ate.trans);
  j["pairs"] = ate.trans.count;
  const Alignment& a = ate.alignment;
  if (a.rotation_well_determined()) {
    j["rot_deg"] = stats_json(ate.rot_deg);
  } else {
    j["rot_deg_withheld"] = rotation_withheld_reason(a);
  }
  json rotation = json::array();
  for (int r = 0; r < 3; ++r)
    rotation.push_back({a.rotation(r, 0), a.rotation(r, 1), a.rotation(r, 2)});
  j["alignment"] = {{"method", to_string(a.method)},
                    {"poses_used", a.poses_used},
                    {"scale", a.scale},
                    {"rotation_ambiguity_deg", a.rotation_ambiguity_deg},
                    {"rotation", rotation},
                    {"translation", {a.translation.x(), a.translation.y(), a.translation.z()}}};
  return j;
}

json rpe_json(const RpeResult& rpe, const RpeOptions& options) {
  return {{"pairs", rpe.pairs.size()},
          {"delta", options.delta},
          {"unit", to_string(options.unit)},
          {"all_pairs", options.all_pairs},
          {"convention", to_string(options.convention)},
          {"scale", options.scale},
          {"rel_delta_tol", options.rel_delta_tol},
          {"trans", stats_json(rpe.trans)},
          {"rot_deg", stats_json(rpe.rot_deg)}};
}

json coverage_json(const Coverage& c) {
  return {{"groundtruth_span_s", c.gt_end - c.gt_start},
          {"estimate_span_s", c.est_end - c.est_start},
          {"overlap_s", c.overlap_s},
          {"fraction_of_groundtruth", c.fraction_of_gt},
          {"estimate_poses", c.est_poses},
          {"matched_estimate_poses", c.matched_est_poses}};
}

json kitti_json(const KittiOdometryResult& kitti, size_t pairs) {
  json lengths = json::array();
  for (const KittiLengthError& l : kitti.lengths)
    lengths.push_back({{"length_m", l.length_m},
                       {"segments", l.segments},
                       {"trans_pct", l.trans_pct},
                       {"rot_deg_per_m", l.rot_deg_per_m}});
  return {{"pairs", pairs},
          {"segments", kitti.segments.size()},
          {"trans_pct", kitti.trans_pct},
          {"rot_deg_per_m", kitti.rot_deg_per_m},
          {"lengths", lengths}};
}

json input_json(const std::filesystem::path& path, const TrajectoryFile& file) {
  const Trajectory& t = file.trajectory;
  json j = {{"format", file.format},
            {"poses", t.size()},
            {"start", t.start_time()},
            {"end", t.end_time()},
            {"zero_quaternions_skipped", file.zero_quaternions_skipped},
            {"non_finite_lines_skipped", file.non_finite_lines_skipped},
            {"duplicate_stamps_dropped", file.duplicate_stamps_dropped},
            {"was_unsorted", file.was_unsorted},
            {"warnings", file.warnings}};
  if (!path.empty()) {
    j["path"] = path.string();
    j["fnv1a64"] = fnv1a64_file(path);
  }
  return j;
}

namespace {

// The JSON pointer of the first non-finite number in `j` (nlohmann writes those as null).
std::optional<std::string> find_non_finite(const json& j, const std::string& at) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return at;
  if (j.is_structured())
    for (const auto& [key, value] : j.items())
      if (auto found = find_non_finite(value, at + "/" + key)) return found;
  return std::nullopt;
}

}  // namespace

void merge_into_metrics_file(const std::filesystem::path& path, const json& update) {
  // A last guard: the metrics check their own results, but null must never reach the file.
  if (const auto at = find_non_finite(update, ""))
    throw_input_error(path.string(), "not written: the value at " + *at +
                                         " is not finite (the input overflowed the arithmetic)");
  json merged = json::object();
  if (std::filesystem::exists(path)) {
    merged = read_metrics_file(path);
  }
  merge_metrics(merged, update);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  out << merged.dump(2) << "\n";
  if (!out) throw_input_error(path.string(), "cannot write file");
}

void merge_metrics(json& merged, const json& update) {
  for (const auto& [key, value] : update.items()) {
    const bool replace = key == "ate" || key == "rpe" || key == "kitti" || !value.is_object() ||
                         !merged.contains(key) || !merged[key].is_object();
    if (replace) {
      merged[key] = value;
    } else {
      merged[key].update(value);
    }
  }
}

json read_metrics_file(const std::filesystem::path& path) {
  if (path_kind(path) != PathKind::kFile)
    throw_input_error(path.string(), "no metrics file here (run `slamkit eval ... --out` first)");
  std::ifstream in(path);
  if (!in) throw_input_error(path.string(), "cannot read metrics file");
  const json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw_input_error(path.string(), "not a JSON object (a slamkit metrics.json?)");
  return j;
}

void require_complete_run(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / "run.json";
  if (!std::filesystem::exists(path)) return;
  std::ifstream in(path);
  const json j = json::parse(in, nullptr, false);
  const json status = j.is_object() ? j.value("status", json()) : json();
  if (status == "complete") return;
  throw_input_error(
      path.string(),
      "the run is not complete (status " +
          (status.is_string() ? "'" + printable(status.get<std::string>(), 40) + "'"
                              : std::string("unreadable")) +
          "): it stopped on an error, was interrupted or is still running; run it again");
}

}  // namespace slamkit::eval
