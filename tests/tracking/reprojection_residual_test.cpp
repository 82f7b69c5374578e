#include "tracking/reprojection_residual.h"

#include <ceres/numeric_diff_cost_function.h>
#include <gtest/gtest.h>

namespace slamkit {
namespace {

// The residual alone, for Ceres' numeric differentiation: an independent check of the
// hand-derived Jacobians.
template <int kDim>
struct ResidualOnly {
  const ReprojectionResidual<kDim>* residual;
  bool operator()(const double* q, const double* t, double* r) const {
    const double* parameters[] = {q, t};
    return residual->Evaluate(parameters, r, nullptr);
  }
};

template <int kDim>
void expect_jacobians_match_numeric(const Eigen::Quaterniond& q_c_w, const Eigen::Vector3d& t_c_w) {
  const ResidualIntrinsics k{520.9, 521.0, 325.1, 249.7, 40.0};
  const ReprojectionResidual<kDim> analytic(Eigen::Vector3d(0.4, -0.3, 2.1),
                                            Eigen::Vector2d(300, 260), 2.05, 1.44, k);
  ceres::NumericDiffCostFunction<ResidualOnly<kDim>, ceres::CENTRAL, kDim, 4, 3> numeric(
      new ResidualOnly<kDim>{&analytic});
  const double q[4] = {q_c_w.x(), q_c_w.y(), q_c_w.z(), q_c_w.w()};
  const double* parameters[] = {q, t_c_w.data()};
  double r_a[kDim], r_n[kDim], dq_a[kDim * 4], dt_a[kDim * 3], dq_n[kDim * 4], dt_n[kDim * 3];
  double* jacobians_a[] = {dq_a, dt_a};
  double* jacobians_n[] = {dq_n, dt_n};
  ASSERT_TRUE(analytic.Evaluate(parameters, r_a, jacobians_a));
  ASSERT_TRUE(numeric.Evaluate(parameters, r_n, jacobians_n));
  for (int i = 0; i < kDim; ++i) EXPECT_DOUBLE_EQ(r_a[i], r_n[i]);
  for (int i = 0; i < kDim * 4; ++i)
    EXPECT_NEAR(dq_a[i], dq_n[i], 1e-5 * (1 + std::abs(dq_n[i]))) << i;
  for (int i = 0; i < kDim * 3; ++i)
    EXPECT_NEAR(dt_a[i], dt_n[i], 1e-5 * (1 + std::abs(dt_n[i]))) << i;
}

TEST(ReprojectionResidual, AnalyticJacobiansEqualNumericDifferentiation) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, -1, 0.4).normalized()));
  const Eigen::Vector3d t(0.05, 0.1, -0.2);
  expect_jacobians_match_numeric<2>(q, t);
  expect_jacobians_match_numeric<3>(q, t);
  expect_jacobians_match_numeric<3>(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero());
}

TEST(ReprojectionResidual, PointBehindTheCameraHasNoResidual) {
  const ResidualIntrinsics k{520.9, 521.0, 325.1, 249.7, 40.0};
  const ReprojectionResidual<2> residual(Eigen::Vector3d(0, 0, -1), Eigen::Vector2d(300, 260), 0, 1,
                                         k);
  const double q[4] = {0, 0, 0, 1}, t[3] = {0, 0, 0};
  const double* parameters[] = {q, t};
  double r[2];
  EXPECT_FALSE(residual.Evaluate(parameters, r, nullptr));
}

}  // namespace
}  // namespace slamkit
