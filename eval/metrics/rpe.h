#pragma once
// Relative pose error: drift over a fixed delta (seconds, frames, metres, degrees, radians).
//   tum (default): exactly evaluate_rpe.py --fixed_delta: for each estimated pose i, j is the
//     estimated pose whose delta index (time, frame number, path length or accumulated
//     rotation) is closest to index_i + delta, and the pair is dropped when j is the last
//     pose. Both are matched to their nearest groundtruth pose in time; a pair is dropped
//     when either match is more than 2 x (median groundtruth interval) away.
//     E = (P_j^-1 P_i)^-1 (Q_j^-1 Q_i), rotation angle = arccos((trace R - 1) / 2).
//     The script randomly samples 10000 pairs when it finds more; slamkit never samples.
//   evo: evo's metrics.RPE on the associated pose list (eval::associate), pairs chosen as
//     evo's filters.id_pairs_from_delta does (see evo_pairs in rpe.cpp for each unit),
//     E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j), rotation angle from the SO(3) log.
// In both, estimated positions are first multiplied by `scale` (a Sim(3) alignment's, as
// evo_rpe -as does before computing anything; rotation and translation of an alignment
// cancel in relative poses), so metre windows measure the scaled path.
// See eval/README.md for the details of each unit and of --all-pairs.
#include <string>
#include <vector>

#include "core/association.h"
#include "core/trajectory.h"
#include "eval/metrics/statistics.h"

namespace slamkit::eval {

enum class DeltaUnit { kSeconds, kFrames, kMetres, kDegrees, kRadians };
enum class RpeConvention { kTum, kEvo };

struct RpeOptions {
  double delta = 1.0;
  DeltaUnit unit = DeltaUnit::kSeconds;
  // tum: every ordered pair i < j of estimated poses, delta ignored (the script's mode
  // without --fixed_delta, minus its i == j / j < i pairs and random sampling).
  // evo: evo's all_pairs (a pair starting at every pose instead of consecutive windows).
  bool all_pairs = false;
  RpeConvention convention = RpeConvention::kTum;
  double offset = 0.0;  // added to estimate stamps (tum convention)
  double scale = 1.0;   // estimated positions are scaled by this first (Sim(3) alignment)
  // evo's rel_delta_tol (evo_rpe --delta_tol): all-pairs windows in metres and degrees accept
  // a pair whose distance or angle is within rel_delta_tol * delta of delta.
  double rel_delta_tol = 0.1;
};

struct RpePair {
  double stamp_est_i, stamp_est_j, stamp_gt_i, stamp_gt_j;
  double trans;    // metres
  double rot_deg;  // degrees
};

struct RpeResult {
  std::vector<RpePair> pairs;  // in order of i
  ErrorStats trans;
  ErrorStats rot_deg;
};

// `associated` (from eval::associate) is used by the evo convention only. Throws InputError
// (naming `est_name`) when fewer than 2 valid pairs remain, as the script does.
RpeResult compute_rpe(const Trajectory& gt, const Trajectory& est,
                      const std::vector<IndexPair>& associated, const RpeOptions& options,
                      const std::string& est_name = "estimate");

// The script's find_closest_index (binary search remembering the closest visited element;
// ties go to the first one visited). Exposed for tests.
size_t find_closest_index(const std::vector<double>& sorted, double value);

std::string to_string(DeltaUnit unit);
DeltaUnit parse_delta_unit(const std::string& text);  // s, f, m, deg, rad
std::string to_string(RpeConvention convention);
RpeConvention parse_rpe_convention(const std::string& text);  // tum, evo

}  // namespace slamkit::eval
