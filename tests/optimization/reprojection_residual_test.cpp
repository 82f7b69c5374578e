#include "optimization/reprojection_residual.h"

#include <ceres/rotation.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

#include "optimization/motion_ba_objective.h"

namespace slamkit {
namespace {

const ResidualIntrinsics kIntrinsics{520.9, 521.0, 325.1, 249.7, 40.0};

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).matrix();
}

// Central differences of f: R^6 -> R^m at x: an independent check of the hand-derived
// Jacobians, through Ceres' own angle-axis exponential.
template <typename F>
Eigen::MatrixXd numeric_jacobian(const F& f, const Eigen::Matrix<double, 6, 1>& x, int m) {
  Eigen::MatrixXd J(m, 6);
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Eigen::Matrix<double, 6, 1> plus = x, minus = x;
    plus(j) += h, minus(j) -= h;
    J.col(j) = (f(plus) - f(minus)) / (2 * h);
  }
  return J;
}

Eigen::Matrix3d exp_so3(const Eigen::Vector3d& w) {
  Eigen::Matrix3d R;
  ceres::AngleAxisToRotationMatrix(w.data(), R.data());
  return R;
}

TEST(ReprojectionResidual, JacobianOfTheIncrementEqualsNumericDifferentiation) {
  const Eigen::Matrix3d R_0 = rotation(0.3, {0.2, -1, 0.4});
  const Eigen::Vector3d t_0(0.05, 0.1, -0.2);
  Eigen::Matrix<double, 6, 1> x;
  x << 0.02, -0.03, 0.01, 0.01, 0.02, -0.01;  // away from 0, where J_l matters
  for (const double depth : {2.05, 0.0}) {
    const ReprojectionResidual residual({0.4, -0.3, 2.1}, {300, 260}, depth, 1.44, kIntrinsics);
    const int dim = residual.dimension();
    EXPECT_EQ(dim, depth > 0 ? 3 : 2);
    const auto at = [&](const Eigen::Matrix<double, 6, 1>& p) {
      ReprojectionResidual::Vector r;
      EXPECT_TRUE(residual.evaluate(exp_so3(p.head<3>()) * R_0, t_0 + p.tail<3>(), r));
      return Eigen::VectorXd(r.head(dim));
    };
    ReprojectionResidual::Vector r;
    ReprojectionResidual::Jacobian J;
    ASSERT_TRUE(residual.evaluate(exp_so3(x.head<3>()) * R_0, t_0 + x.tail<3>(), r,
                                  so3_left_jacobian(x.head<3>()), &J));
    const Eigen::MatrixXd expected = numeric_jacobian(at, x, dim);
    EXPECT_LT((J.topRows(dim) - expected).norm(), 1e-6 * expected.norm()) << depth;
    const Eigen::VectorXd again = at(x);
    for (int i = 0; i < dim; ++i) EXPECT_NEAR(r(i), again(i), 1e-12);
  }
}

TEST(ReprojectionResidual, PixelResidualIsTheProjectionErrorOverSigma) {
  // A point on the optical axis 2 m ahead projects onto the principal point; observed 3 px to
  // the right with sigma 1.5, the residual is -2 in u, 0 in v; the disparity bf/z matches.
  const ReprojectionResidual residual({0, 0, 2}, {kIntrinsics.cx + 3, kIntrinsics.cy}, 2.0, 1.5,
                                      kIntrinsics);
  ReprojectionResidual::Vector r;
  ASSERT_TRUE(residual.evaluate(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), r));
  EXPECT_NEAR(r(0), -2.0, 1e-12);
  EXPECT_NEAR(r(1), 0.0, 1e-12);
  EXPECT_NEAR(r(2), 0.0, 1e-12);
}

TEST(ReprojectionResidual, PointBehindTheCameraHasNoResidual) {
  const ReprojectionResidual residual({0, 0, -1}, {300, 260}, 0, 1, kIntrinsics);
  ReprojectionResidual::Vector r;
  EXPECT_FALSE(residual.evaluate(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), r));
}

TEST(MotionBaObjective, HuberCostAndExactJacobianOfTheRescaledResiduals) {
  // One inlier-sized and one outlier-sized residual (with and without depth), robust delta 2.
  const std::vector<ReprojectionResidual> residuals = {
      ReprojectionResidual({0.4, -0.3, 2.1}, {300, 260}, 2.05, 1.0, kIntrinsics),
      ReprojectionResidual({-0.5, 0.2, 1.7}, {120, 330}, 0.0, 1.2, kIntrinsics)};
  const Eigen::Matrix3d R_0 = rotation(0.2, {1, 0.3, -0.2});
  const Eigen::Vector3d t_0(0.02, -0.05, 0.1);
  const double delta = 2.0;
  const MotionBaObjective objective({{&residuals[0], delta}, {&residuals[1], delta}}, R_0, t_0);
  ASSERT_EQ(objective.NumResiduals(), 5);

  Eigen::Matrix<double, 6, 1> x;
  x << 0.01, 0.02, -0.01, 0.01, -0.02, 0.03;
  const auto at = [&](const Eigen::Matrix<double, 6, 1>& p) {
    Eigen::VectorXd r(5);
    EXPECT_TRUE(objective(p.data(), r.data(), nullptr));
    return r;
  };
  // Half the squared norm of each rescaled residual is its Huber cost rho(s) / 2.
  const Eigen::VectorXd scaled = at(x);
  double s_first = 0, s_second = 0;
  for (int i = 0; i < 2; ++i) {
    ReprojectionResidual::Vector r;
    ASSERT_TRUE(residuals[i].evaluate(exp_so3(x.head<3>()) * R_0, t_0 + x.tail<3>(), r));
    (i == 0 ? s_first : s_second) = r.squaredNorm();
  }
  const auto huber = [&](double s) {
    return s <= delta * delta ? s : 2 * delta * std::sqrt(s) - delta * delta;
  };
  ASSERT_GT(std::max(s_first, s_second), delta * delta);  // the Huber branch is exercised
  EXPECT_NEAR(scaled.head<3>().squaredNorm(), huber(s_first), 1e-9 * huber(s_first));
  EXPECT_NEAR(scaled.tail<2>().squaredNorm(), huber(s_second), 1e-9 * huber(s_second));

  Eigen::Matrix<double, Eigen::Dynamic, 6> J(5, 6);
  Eigen::VectorXd r(5);
  ASSERT_TRUE(objective(x.data(), r.data(), J.data()));
  const Eigen::MatrixXd expected = numeric_jacobian(at, x, 5);
  EXPECT_LT((J - expected).norm(), 1e-6 * expected.norm());
}

}  // namespace
}  // namespace slamkit
