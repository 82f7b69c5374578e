#pragma once
// Plausibility checks on a tracked pose: the solvers can return a confident but wrong pose.
#include <Eigen/Geometry>

#include "core/settings/tracking_settings.h"

namespace slamkit {

enum class TrackingFailure {
  kNone,
  kTooFewInliers,
  kImplausibleJump,  // faster than settings.max_speed or max_angular_speed_deg
};

struct MotionCheck {
  TrackingFailure failure = TrackingFailure::kNone;
  double speed = 0;              // m/s between the two poses
  double angular_speed_deg = 0;  // deg/s
  bool ok() const { return failure == TrackingFailure::kNone; }
};

// Checks the motion from T_w_prev to T_w_curr over dt seconds (floored at settings.min_dt)
// and the inlier count of the solver that produced T_w_curr.
MotionCheck check_tracking(const Eigen::Isometry3d& T_w_prev, const Eigen::Isometry3d& T_w_curr,
                           double dt, int num_inliers, const FailureSettings& settings);

}  // namespace slamkit
