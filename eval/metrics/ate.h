#pragma once
// Absolute trajectory error: align the matched estimate to groundtruth, then measure each
// matched pose's position error (the benchmark's evaluate_ate.py) and rotation error.
#include <string>
#include <vector>

#include "core/association.h"
#include "core/trajectory.h"
#include "eval/metrics/alignment.h"
#include "eval/metrics/statistics.h"

namespace slamkit::eval {

struct AteResult {
  Alignment alignment;
  // Per matched pair, in estimate time order:
  std::vector<double> stamps;                // estimate stamps
  std::vector<Eigen::Vector3d> est_aligned;  // aligned estimated positions
  std::vector<Eigen::Vector3d> gt_positions;
  std::vector<double> trans_errors;    // metres: |aligned estimate - groundtruth|
  std::vector<double> rot_errors_deg;  // angle of R_gt^-1 * R_aligned_estimate
  ErrorStats trans;
  ErrorStats rot_deg;  // meaningful only if alignment.rotation_well_determined()
};

struct AteOptions {
  AlignMethod align = AlignMethod::kSe3;
  size_t align_first = 0;  // align on the first N pairs only (0 = all)
};

// `pairs` as from eval::associate (first: gt index, second: est index). Throws InputError
// (naming the file) when the alignment is undetermined (see eval::align).
AteResult compute_ate(const Trajectory& gt, const Trajectory& est,
                      const std::vector<IndexPair>& pairs, const AteOptions& options,
                      const std::string& gt_name = "groundtruth",
                      const std::string& est_name = "estimate");

// ATE RMSE (metres) with the benchmark's defaults: associate within 0.02 s, SE(3) alignment.
// Throws InputError (naming the files) when fewer than 2 poses match.
double ate_rmse(const Trajectory& gt, const Trajectory& est,
                const std::string& gt_name = "groundtruth",
                const std::string& est_name = "estimate");

// The whole estimate (matched or not) moved by the alignment, for aligned.txt.
Trajectory apply_alignment(const Trajectory& est, const Alignment& alignment);

}  // namespace slamkit::eval
