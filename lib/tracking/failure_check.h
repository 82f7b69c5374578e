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

// What vouches for a pose: the solver's inliers (RANSAC's, or dense alignment's
// correspondences) and, when the motion-only BA refined it, the matches it kept of those it
// was given.
struct PoseSupport {
  int solver_inliers = 0;
  bool refined = false;
  int refined_inliers = 0;
  int matches = 0;
};

struct MotionCheck {
  TrackingFailure failure = TrackingFailure::kNone;
  double speed = 0;              // m/s between the two poses
  double angular_speed_deg = 0;  // deg/s
  bool trusted = false;          // strong enough support to skip the speed limits
  bool ok() const { return failure == TrackingFailure::kNone; }
};

// Checks the motion from T_w_prev to T_w_curr over dt seconds (floored at settings.min_dt)
// and the support of the solver that produced T_w_curr.
MotionCheck check_tracking(const Eigen::Isometry3d& T_w_prev, const Eigen::Isometry3d& T_w_curr,
                           double dt, const PoseSupport& support,
                           const FailureSettings& settings);

}  // namespace slamkit
