#include "eval/metrics_json.h"

#include <fstream>

#include "core/error.h"
#include "eval/checksum.h"

namespace slamkit::eval {

using nlohmann::json;

json stats_json(const ErrorStats& s) {
  return {{"rmse", s.rmse}, {"mean", s.mean}, {"median", s.median},
          {"std", s.std},   {"min", s.min},   {"max", s.max}};
}

json ate_json(const AteResult& ate) {
  json j = stats_json(ate.trans);
  j["pairs"] = ate.trans.count;
  j["rot_deg"] = stats_json(ate.rot_deg);
  const Alignment& a = ate.alignment;
  json rotation = json::array();
  for (int r = 0; r < 3; ++r)
    rotation.push_back({a.rotation(r, 0), a.rotation(r, 1), a.rotation(r, 2)});
  j["alignment"] = {{"method", to_string(a.method)},
                    {"poses_used", a.poses_used},
                    {"scale", a.scale},
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

json input_json(const std::filesystem::path& path, const TrajectoryFile& file) {
  const Trajectory& t = file.trajectory;
  return {{"path", path.string()},
          {"fnv1a64", fnv1a64_file(path)},
          {"poses", t.size()},
          {"start", t.start_time()},
          {"end", t.end_time()},
          {"zero_quaternions_skipped", file.zero_quaternions_skipped},
          {"non_finite_lines_skipped", file.non_finite_lines_skipped},
          {"duplicate_stamps_dropped", file.duplicate_stamps_dropped},
          {"was_unsorted", file.was_unsorted},
          {"warnings", file.warnings}};
}

void merge_into_metrics_file(const std::filesystem::path& path, const json& update) {
  json merged = json::object();
  if (std::filesystem::exists(path)) {
    merged = read_metrics_file(path);
  }
  for (const auto& [key, value] : update.items()) {
    const bool replace = key == "ate" || key == "rpe" || !value.is_object() ||
                         !merged.contains(key) || !merged[key].is_object();
    if (replace) {
      merged[key] = value;
    } else {
      merged[key].update(value);
    }
  }
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  out << merged.dump(2) << "\n";
  if (!out) throw_input_error(path.string(), "cannot write file");
}

json read_metrics_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw_input_error(path.string(), "cannot read metrics file");
  const json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw_input_error(path.string(), "not a JSON object (a slamkit metrics.json?)");
  return j;
}

}  // namespace slamkit::eval
