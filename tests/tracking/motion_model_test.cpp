#include "tracking/motion_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace slamkit {
namespace {

double pose_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

// Constant linear acceleration, and constant angular acceleration about a fixed axis.
StampedPose accelerating(double t) {
  const Eigen::Vector3d p0(0.5, -0.2, 1.0), v0(0.3, 0.1, -0.2), a(0.8, -0.5, 0.4);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.2, 1, -0.4).normalized();
  const double w0 = 0.6, alpha = 2.5;  // rad/s, rad/s^2
  StampedPose s;
  s.stamp = t;
  s.T_w_c.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 0, 1).normalized()) *
                     Eigen::AngleAxisd(w0 * t + 0.5 * alpha * t * t, axis).matrix();
  s.T_w_c.translation() = p0 + v0 * t + 0.5 * a * t * t;
  return s;
}

// A constant body twist (screw motion): T(t) = T0 exp(xi t).
StampedPose screw(double t) {
  const Eigen::Vector3d w = Eigen::Vector3d(0.3, -0.8, 0.5) * t;  // rad/s * s
  const Eigen::Vector3d axis = w.normalized(), v = Eigen::Vector3d(0.4, 0.1, -0.3) * t;
  const double theta = w.norm();
  Eigen::Matrix3d W;
  W << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
  const Eigen::Matrix3d V = Eigen::Matrix3d::Identity() + (1 - std::cos(theta)) / theta * W +
                            (theta - std::sin(theta)) / theta * W * W;
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.linear() = Eigen::AngleAxisd(theta, axis).matrix();
  step.translation() = V * v;
  Eigen::Isometry3d T0 = Eigen::Isometry3d::Identity();
  T0.linear() = Eigen::AngleAxisd(1.1, Eigen::Vector3d(0, 1, 1).normalized()).matrix();
  T0.translation() = Eigen::Vector3d(1, 2, 3);
  return {t, T0 * step};
}

TEST(MotionModel, LinearVelocityExactForConstantAcceleration) {
  // The keyframe case: velocities of the 2 frames before the current one (irregular gaps).
  const StampedPose f0 = accelerating(0.0), f1 = accelerating(0.031), f2 = accelerating(0.068);
  const double t = 0.1;
  const Eigen::Isometry3d predicted =
      predict_linear_velocity(velocity_between(f0, f1), velocity_between(f1, f2), f2, t);
  EXPECT_LT(pose_error(predicted, accelerating(t).T_w_c), 1e-6);
  // Far ahead too: the model is exact, not first order.
  const Eigen::Isometry3d far =
      predict_linear_velocity(velocity_between(f0, f1), velocity_between(f1, f2), f2, 0.5);
  EXPECT_LT(pose_error(far, accelerating(0.5).T_w_c), 1e-6);
}

TEST(MotionModel, LinearVelocityFromKeyframeIntervals) {
  // The non-keyframe case: each keyframe's velocity over the interval ending at it, then
  // integrated from the last frame (not a keyframe).
  const auto v_kf1 = velocity_between(accelerating(0.20), accelerating(0.233));
  const auto v_kf2 = velocity_between(accelerating(0.40), accelerating(0.433));
  const StampedPose last = accelerating(0.5);
  EXPECT_LT(
      pose_error(predict_linear_velocity(v_kf1, v_kf2, last, 0.533), accelerating(0.533).T_w_c),
      1e-6);
}

TEST(MotionModel, VelocityIsTheMidpointRate) {
  const StampedPose a = accelerating(0.1), b = accelerating(0.2);
  const StampedVelocity v = velocity_between(a, b);
  EXPECT_DOUBLE_EQ(v.stamp, 0.15);
  // d/dt (v0 t + a t^2 / 2) at 0.15 s.
  EXPECT_LT((v.linear - (Eigen::Vector3d(0.3, 0.1, -0.2) + 0.15 * Eigen::Vector3d(0.8, -0.5, 0.4)))
                .norm(),
            1e-12);
  EXPECT_NEAR(v.angular.norm(), 0.6 + 2.5 * 0.15, 1e-12);
  EXPECT_THROW(velocity_between(b, a), std::invalid_argument);
  EXPECT_THROW(velocity_between(a, a), std::invalid_argument);
}

TEST(MotionModel, ExtrapolationIsLinearInTime) {
  StampedVelocity older, newer;
  older.stamp = 1.0, older.linear = {1, 0, 0}, older.angular = {0, 0, 0.1};
  newer.stamp = 2.0, newer.linear = {2, 0, 0}, newer.angular = {0, 0, 0.3};
  const StampedVelocity v = extrapolate_velocity(older, newer, 3.5);
  EXPECT_DOUBLE_EQ(v.stamp, 3.5);
  EXPECT_NEAR(v.linear.x(), 3.5, 1e-12);
  EXPECT_NEAR(v.angular.z(), 0.6, 1e-12);
  // Two samples at the same time: constant velocity.
  EXPECT_EQ(extrapolate_velocity(newer, newer, 5.0).linear, newer.linear);
}

TEST(MotionModel, ConstantVelocityExactForConstantTwist) {
  const StampedPose prev = screw(1.0), last = screw(1.033);
  // Same gap as the last one (the ORB-SLAM2 case), a longer one, and a dropped frame.
  for (double t : {1.066, 1.08, 1.2})
    EXPECT_LT(pose_error(predict_constant_velocity(prev, last, t), screw(t).T_w_c), 1e-9) << t;
  EXPECT_LT(pose_error(predict_constant_velocity(prev, last, last.stamp), last.T_w_c), 1e-12);
  EXPECT_EQ(predict_constant_velocity(last, last, 2.0).matrix(), last.T_w_c.matrix());
}

TEST(MotionModel, IntegrationOfZeroVelocityStaysPut) {
  const StampedPose last = accelerating(0.3);
  EXPECT_LT(pose_error(integrate_velocity(last, StampedVelocity{}, 0.4), last.T_w_c), 1e-15);
}

}  // namespace
}  // namespace slamkit
