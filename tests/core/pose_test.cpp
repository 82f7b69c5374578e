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

// scipy 1.10's Rotation.from_matrix(m).as_quat() (x y z w) for two matrices rounded to 7 digits:
// a small rotation (the trace formula) and one of 100 degrees whose trace (0.81) is positive
// but below its first diagonal element (0.88), where Eigen's conversion takes another formula.
TEST(Pose, QuaternionFromMatrixIsScipysOnMatricesThatAreNotQuiteRotations) {
  Eigen::Matrix3d small, large;
  small << 9.999978e-01, 5.272628e-04, -2.066935e-03, -5.296506e-04, 9.999992e-01, -1.154865e-03,
      2.066324e-03, 1.155958e-03, 9.999971e-01;
  large << 0.8797799, -0.2048948, 0.4289585, 0.421291, -0.0819807, -0.9032127, 0.2202299,
      0.9753447, 0.0141954;
  const Eigen::Vector4d scipy_small(5.7770617712661263e-04, -1.0333155139810213e-03,
                                    -2.6422854535716940e-04, 9.9999926434867803e-01);
  const Eigen::Vector4d scipy_large(0.6977759576229146, 0.07753068584351361, 0.23259198587430482,
                                    0.673051761622467);
  EXPECT_LT((quaternion_from_matrix(small).coeffs() - scipy_small).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((quaternion_from_matrix(large).coeffs() - scipy_large).cwiseAbs().maxCoeff(), 1e-15);
  // Eigen's own conversion of the second is a different quaternion, 1e-7 away.
  const Eigen::Quaterniond eigen = Eigen::Quaterniond(large).normalized();
  EXPECT_GT((eigen.coeffs() - scipy_large).cwiseAbs().maxCoeff(), 1e-9);
  // On an exact rotation every formula gives the rotation's quaternion.
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, -2, 3).normalized()));
  EXPECT_LT(quaternion_from_matrix(q.toRotationMatrix()).angularDistance(q), 1e-14);
}

}  // namespace
}  // namespace slamkit
