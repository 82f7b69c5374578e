#include "tracking/failure_check.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slamkit {
namespace {

Eigen::Isometry3d moved(double metres, double degrees) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(degrees * M_PI / 180, Eigen::Vector3d::UnitY()).matrix();
  T.translation() = Eigen::Vector3d(metres, 0, 0);
  return T;
}

const Eigen::Isometry3d kStart = moved(1.0, 30);
constexpr double kFrame = 1.0 / 30;

TEST(FailureCheck, HandheldMotionPasses) {
  const MotionCheck c = check_tracking(kStart, kStart * moved(0.02, 1.5), kFrame, 200, {});
  EXPECT_TRUE(c.ok());
  EXPECT_NEAR(c.speed, 0.6, 1e-9);
  EXPECT_NEAR(c.angular_speed_deg, 45, 1e-9);
}

TEST(FailureCheck, JumpsAreFailures) {
  const FailureSettings s;
  // 0.3 m in one frame is 9 m/s; 10 degrees in one frame is 300 deg/s.
  EXPECT_EQ(check_tracking(kStart, kStart * moved(0.3, 0), kFrame, 200, s).failure,
            TrackingFailure::kImplausibleJump);
  EXPECT_EQ(check_tracking(kStart, kStart * moved(0, 10), kFrame, 200, s).failure,
            TrackingFailure::kImplausibleJump);
  // The same 0.3 m over a second is a walk.
  EXPECT_TRUE(check_tracking(kStart, kStart * moved(0.3, 0), 1.0, 200, s).ok());
}

TEST(FailureCheck, TooFewInliersIsAFailure) {
  EXPECT_EQ(check_tracking(kStart, kStart, kFrame, 9, {}).failure, TrackingFailure::kTooFewInliers);
  EXPECT_TRUE(check_tracking(kStart, kStart, kFrame, 10, {}).ok());
}

TEST(FailureCheck, ZeroTimeGapDoesNotBlowUp) {
  const MotionCheck c = check_tracking(kStart, kStart * moved(0.01, 0), 0.0, 200, {});
  EXPECT_NEAR(c.speed, 1.0, 1e-9);  // over min_dt = 0.01 s
  EXPECT_TRUE(std::isfinite(c.angular_speed_deg));
}

}  // namespace
}  // namespace slamkit
