#include "eval/metrics/coverage.h"

#include <algorithm>
#include <cstdio>

namespace slamkit::eval {

Coverage compute_coverage(const Trajectory& gt, const Trajectory& est, size_t matched) {
  Coverage c;
  c.gt_start = gt.start_time();
  c.gt_end = gt.end_time();
  c.est_start = est.start_time();
  c.est_end = est.end_time();
  c.overlap_s = std::max(0.0, std::min(c.gt_end, c.est_end) - std::max(c.gt_start, c.est_start));
  const double span = c.gt_end - c.gt_start;
  c.fraction_of_gt = span > 0 ? c.overlap_s / span : 1.0;
  c.est_poses = est.size();
  c.matched_est_poses = matched;
  return c;
}

std::optional<std::string> coverage_warning(const Coverage& c) {
  const double matched = c.est_poses ? double(c.matched_est_poses) / c.est_poses : 0.0;
  if (c.fraction_of_gt >= 0.9 && matched >= 0.9) return std::nullopt;
  char text[512];
  std::snprintf(text, sizeof text,
                "estimate covers %.0f%% of groundtruth time span (%.3f s of %.3f s: %.6f .. "
                "%.6f); %zu of %zu estimated poses (%.0f%%) matched groundtruth; errors are "
                "for the overlap only",
                100.0 * c.fraction_of_gt, c.overlap_s, c.gt_end - c.gt_start,
                std::max(c.gt_start, c.est_start), std::min(c.gt_end, c.est_end),
                c.matched_est_poses, c.est_poses, 100.0 * matched);
  return std::string(text);
}

}  // namespace slamkit::eval
