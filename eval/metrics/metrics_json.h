#pragma once
// metrics.json: the results as data, which plots, comparisons and scripts read afterwards.
// Layout (keep stable, see eval/README.md):
//   {"ate": {...}, "rpe": {...}, "settings": {...}, "inputs": {"groundtruth", "estimate"},
//    "coverage": {...}}
// Each command writes its own sections and merges into an existing file.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "eval/metrics/kitti_odometry.h"
#include <string>

#include "eval/metrics/ate.h"
#include "eval/metrics/coverage.h"
#include "eval/metrics/rpe.h"
#include "eval/metrics/statistics.h"
#include "io/trajectory_io.h"

namespace slamkit::eval {

nlohmann::json stats_json(const ErrorStats& s);  // rmse, mean, median, std, min, max
// "rot_deg" is left out, and "rot_deg_withheld" gives the reason, when the alignment does not
// determine the rotation (Alignment::rotation_well_determined).
nlohmann::json ate_json(const AteResult& ate);
std::string rotation_withheld_reason(const Alignment& a);
nlohmann::json rpe_json(const RpeResult& rpe, const RpeOptions& options);
nlohmann::json coverage_json(const Coverage& c);
nlohmann::json kitti_json(const KittiOdometryResult& kitti, size_t pairs);
// path and fnv1a64 checksum (left out when `path` is empty: a trajectory given in memory),
// format, poses, start, end, skipped-line counts and warnings.
nlohmann::json input_json(const std::filesystem::path& path, const TrajectoryFile& file);

// Merges `update` into the JSON file at `path` (created if missing): "ate" and "rpe" are
// replaced whole, the other top-level objects ("settings", "inputs", "coverage") key by key,
// so `eval ate` and `eval rpe` can share one file. Throws InputError if the existing file is
// not a JSON object (rather than clobbering it) or if `update` holds a non-finite number.
void merge_into_metrics_file(const std::filesystem::path& path, const nlohmann::json& update);
// The same merge of `update` into `merged`, in memory.
void merge_metrics(nlohmann::json& merged, const nlohmann::json& update);

// Reads a metrics.json; InputError naming the file when missing or malformed.
nlohmann::json read_metrics_file(const std::filesystem::path& path);

// Refuses (InputError naming run.json) a run folder whose run.json, written last by `slamkit
// run` and `track`, says other than "complete": the run was interrupted or is still going.
// A folder without run.json (`eval all --out`, other tools) passes.
void require_complete_run(const std::filesystem::path& dir);

}  // namespace slamkit::eval
