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
// A RANSAC pose with 200 inliers that no refinement has checked.
const PoseSupport kUnrefined{200, false, 0, 0};

TEST(FailureCheck, HandheldMotionPasses) {
  const MotionCheck c = check_tracking(kStart, kStart * moved(0.02, 1.5), kFrame, kUnrefined, {});
  EXPECT_TRUE(c.ok());
  EXPECT_NEAR(c.speed, 0.6, 1e-9);
  EXPECT_NEAR(c.angular_speed_deg, 45, 1e-9);
}

TEST(FailureCheck, JumpsAreFailures) {
  const FailureSettings s;
  // 0.3 m in one frame is 9 m/s; 10 degrees in one frame is 300 deg/s.
  EXPECT_EQ(check_tracking(kStart, kStart * moved(0.3, 0), kFrame, kUnrefined, s).failure,
            TrackingFailure::kImplausibleJump);
  EXPECT_EQ(check_tracking(kStart, kStart * moved(0, 10), kFrame, kUnrefined, s).failure,
            TrackingFailure::kImplausibleJump);
  // The same 0.3 m over a second is a walk.
  EXPECT_TRUE(check_tracking(kStart, kStart * moved(0.3, 0), 1.0, kUnrefined, s).ok());
}

TEST(FailureCheck, StronglySupportedPoseMayMoveFast) {
  const FailureSettings s;  // trusted: >= 100 refined inliers, >= 70% of the matches
  const Eigen::Isometry3d whip = kStart * moved(0.15, 20);  // 4.5 m/s, 600 deg/s
  const MotionCheck trusted = check_tracking(kStart, whip, kFrame, {165, true, 165, 205}, s);
  EXPECT_TRUE(trusted.ok());
  EXPECT_TRUE(trusted.trusted);
  // Too few kept inliers, too small a share of the matches, or no refinement: a jump.
  for (const PoseSupport& weak : {PoseSupport{165, true, 99, 120}, PoseSupport{165, true, 140, 201},
                                  PoseSupport{165, false, 0, 205}}) {
    const MotionCheck c = check_tracking(kStart, whip, kFrame, weak, s);
    EXPECT_EQ(c.failure, TrackingFailure::kImplausibleJump);
    EXPECT_FALSE(c.trusted);
  }
  FailureSettings off = s;
  off.trusted_inliers = 0;  // the speed limits alone
  EXPECT_EQ(check_tracking(kStart, whip, kFrame, {165, true, 165, 205}, off).failure,
            TrackingFailure::kImplausibleJump);
}

TEST(FailureCheck, TooFewInliersIsAFailure) {
  EXPECT_EQ(check_tracking(kStart, kStart, kFrame, {9}, {}).failure, TrackingFailure::kTooFewInliers);
  EXPECT_TRUE(check_tracking(kStart, kStart, kFrame, {10}, {}).ok());
}

TEST(FailureCheck, ZeroTimeGapDoesNotBlowUp) {
  const MotionCheck c = check_tracking(kStart, kStart * moved(0.01, 0), 0.0, kUnrefined, {});
  EXPECT_NEAR(c.speed, 1.0, 1e-9);  // over min_dt = 0.01 s
  EXPECT_TRUE(std::isfinite(c.angular_speed_deg));
}

}  // namespace
}  // namespace slamkit
