#pragma once
// Motion models over stamped poses T_w_c (docs/method.md#matching-and-pose): the
// constant-velocity guess used for every frame, and the linearly changing velocity used when
// tracking fails.
#include <Eigen/Geometry>

#include "core/trajectory.h"

namespace slamkit {

// The mean velocity of the camera over an interval. Stamped at the interval's midpoint,
// where it equals the instantaneous velocity when the acceleration is constant.
struct StampedVelocity {
  double stamp = 0;                                   // seconds
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // m/s, world frame: d(t_w_c)/dt
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // rad/s, camera frame: R(t + dt) =
                                                      // R(t) exp([angular dt]x)
};

// Mean velocity from pose a to the later pose b. Throws std::invalid_argument unless
// b.stamp > a.stamp.
StampedVelocity velocity_between(const StampedPose& a, const StampedPose& b);

// The velocity at time t on the straight line through two samples (constant acceleration).
StampedVelocity extrapolate_velocity(const StampedVelocity& older, const StampedVelocity& newer,
                                     double t);

// The pose at t reached from `last` moving with velocity v: translation + v.linear dt,
// rotation R exp([v.angular dt]x), dt = t - last.stamp.
Eigen::Isometry3d integrate_velocity(const StampedPose& last, const StampedVelocity& v, double t);

// The paper's model for tracking failures: the velocity changes linearly in time. `older` and
// `newer` are the two measured velocities (the paper's: when the current frame is a keyframe,
// those of the 2 frames before it, i.e. velocity_between(f[k-3], f[k-2]) and (f[k-2], f[k-1]);
// otherwise those of the 2 keyframes before it, each over the interval ending at that
// keyframe). The velocity line is evaluated at the midpoint of [last.stamp, t] and
// integrated from `last`, which is exact for a constant linear acceleration and a constant
// angular acceleration about a fixed axis.
Eigen::Isometry3d predict_linear_velocity(const StampedVelocity& older,
                                          const StampedVelocity& newer, const StampedPose& last,
                                          double t);

// The constant-velocity guess (ORB-SLAM2's motion model): the last relative motion
// T_prev^-1 T_last repeated, scaled on SE(3) to the time since `last`:
// T_last exp(s log(T_prev^-1 T_last)), s = (t - t_last) / (t_last - t_prev). Exact for a
// constant body twist (screw motion). Returns T_last when the two stamps are equal.
Eigen::Isometry3d predict_constant_velocity(const StampedPose& prev, const StampedPose& last,
                                            double t);

}  // namespace slamkit
