#pragma once
// How much of the groundtruth the estimate covers: an estimate that lost tracking halfway is
// evaluated on the overlap only, and the user must be told so.
#include <optional>
#include <string>

#include "core/trajectory.h"

namespace slamkit::eval {

struct Coverage {
  double gt_start = 0, gt_end = 0;
  double est_start = 0, est_end = 0;
  double overlap_s = 0;       // length of the common time span
  double fraction_of_gt = 0;  // overlap_s / groundtruth span
  size_t est_poses = 0;
  size_t matched_est_poses = 0;  // estimated poses associated with groundtruth
};

Coverage compute_coverage(const Trajectory& gt, const Trajectory& est, size_t matched);

// A warning when the estimate covers less than 90% of the groundtruth span or less than 90%
// of its poses matched; nullopt when coverage is normal.
std::optional<std::string> coverage_warning(const Coverage& c);

}  // namespace slamkit::eval
