#include "eval/sequence_stats/angular_speed.h"

#include <cmath>

#include "core/pose.h"

namespace slamkit::stats {

std::optional<double> angular_speed_deg(const Trajectory& groundtruth, double stamp,
                                        double half_window) {
  const auto before = groundtruth.nearest(stamp - half_window, half_window);
  const auto after = groundtruth.nearest(stamp + half_window, half_window);
  if (!before || !after || *before == *after) return std::nullopt;
  const double dt = groundtruth.stamp(*after) - groundtruth.stamp(*before);
  if (!(dt > 0)) return std::nullopt;
  const double angle =
      rotation_angle(groundtruth.pose(*before).inverse() * groundtruth.pose(*after));
  return angle * 180.0 / M_PI / dt;
}

}  // namespace slamkit::stats
