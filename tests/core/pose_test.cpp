#include "core/pose.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

TEST(Pose, OrthonormalisedProjectsADriftedRotationBackOntoSO3) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  T.linear() = 1.001 * R;  // what rounding drift in long chains of products looks like, enlarged
  T.translation() = Eigen::Vector3d(1, -2, 0.5);
  const Eigen::Isometry3d fixed = orthonormalised(T);
  EXPECT_LT((fixed.linear().transpose() * fixed.linear() - Eigen::Matrix3d::Identity()).norm(),
            1e-12);
  EXPECT_LT((fixed.linear() - R).norm(), 1e-12);
  EXPECT_EQ(fixed.translation(), T.translation());
}

}  // namespace
}  // namespace slamkit
