#include "tracking/failure_check.h"

#include <algorithm>
#include <cmath>

#include "core/pose.h"

namespace slamkit {

MotionCheck check_tracking(const Eigen::Isometry3d& T_w_prev, const Eigen::Isometry3d& T_w_curr,
                           double dt, const PoseSupport& support,
                           const FailureSettings& settings) {
  MotionCheck check;
  const double span = std::max(dt, settings.min_dt);
  const Eigen::Isometry3d T_prev_curr = T_w_prev.inverse() * T_w_curr;
  check.speed = T_prev_curr.translation().norm() / span;
  check.angular_speed_deg = rotation_angle(T_prev_curr) * 180 / M_PI / span;
  check.trusted = settings.trusted_inliers > 0 && support.refined &&
                  support.refined_inliers >= settings.trusted_inliers &&
                  support.refined_inliers >= settings.trusted_inlier_ratio * support.matches;
  if (support.solver_inliers < settings.min_inliers)
    check.failure = TrackingFailure::kTooFewInliers;
  else if (!check.trusted && (check.speed > settings.max_speed ||
                              check.angular_speed_deg > settings.max_angular_speed_deg))
    check.failure = TrackingFailure::kImplausibleJump;
  return check;
}

}  // namespace slamkit
