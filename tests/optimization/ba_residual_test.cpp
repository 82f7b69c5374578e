#include "optimization/ba_residual.h"

#include <ceres/manifold.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace slamkit {
namespace {

const BaIntrinsics kIntrinsics{500, 400, 320, 240};
constexpr double kBf = 40;

// Pose and point, the residual's parameter blocks.
struct Parameters {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

bool evaluate(const BaResidual& residual, const Parameters& x, Eigen::Vector3d& r,
              double** jacobians) {
  const double* blocks[] = {x.q.coeffs().data(), x.t.data(), x.p.data()};
  return residual.Evaluate(blocks, r.data(), jacobians);
}

Eigen::Vector3d evaluate(const BaResidual& residual, const Parameters& x) {
  Eigen::Vector3d r;
  EXPECT_TRUE(evaluate(residual, x, r, nullptr));
  return r;
}

TEST(BaResidual, ValuesMatchHandComputedProjection) {
  // R = 90 degrees about z, t = (0.1, 0, 1): p_w = (0.25, -0.5, 1) -> R p = (0.5, 0.25, 1) ->
  // p_c = (0.6, 0.25, 2): u = 500 * 0.3 + 320 = 470, v = 400 * 0.125 + 240 = 290,
  // disparity 40 / 2 = 20.
  Parameters x;
  x.q = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  x.t = Eigen::Vector3d(0.1, 0, 1);
  x.p = Eigen::Vector3d(0.25, -0.5, 1);
  // Measured (475, 284), depth 2.5 (disparity 16), sigma 2: residuals measured - predicted.
  const BaResidual with_depth(Eigen::Vector2d(475, 284), 2.5, 2, kIntrinsics, kBf);
  EXPECT_EQ(with_depth.dimension(), 3);
  const Eigen::Vector3d r3 = evaluate(with_depth, x);
  EXPECT_NEAR(r3.x(), 2.5, 1e-12);
  EXPECT_NEAR(r3.y(), -3, 1e-12);
  EXPECT_NEAR(r3.z(), -2, 1e-12);

  const BaResidual without_depth(Eigen::Vector2d(475, 284), 0, 2, kIntrinsics, kBf);
  EXPECT_EQ(without_depth.dimension(), 2);
  const Eigen::Vector3d r2 = evaluate(without_depth, x);
  EXPECT_NEAR(r2.x(), 2.5, 1e-12);
  EXPECT_NEAR(r2.y(), -3, 1e-12);
  EXPECT_EQ(r2.z(), 0);
}

// Analytic Jacobians, taken to the tangent space as Ceres does (J_q times PlusJacobian), against
// central differences: through the manifold's Plus for the rotation, plainly for t and p.
void expect_jacobians_match_central_differences(const BaResidual& residual, const Parameters& x) {
  using RowMajor34 = Eigen::Matrix<double, 3, 4, Eigen::RowMajor>;
  using RowMajor33 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
  RowMajor34 J_q;
  RowMajor33 J_t, J_p;
  double* jacobians[] = {J_q.data(), J_t.data(), J_p.data()};
  Eigen::Vector3d r;
  ASSERT_TRUE(evaluate(residual, x, r, jacobians));

  const ceres::EigenQuaternionManifold manifold;
  Eigen::Matrix<double, 4, 3, Eigen::RowMajor> P;
  manifold.PlusJacobian(x.q.coeffs().data(), P.data());
  const Eigen::Matrix3d J_delta = J_q * P;

  constexpr double h = 1e-6;
  Eigen::Matrix3d numeric_delta, numeric_t, numeric_p;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(k);
    Parameters plus = x, minus = x;
    manifold.Plus(x.q.coeffs().data(), step.data(), plus.q.coeffs().data());
    const Eigen::Vector3d negative_step = -step;
    manifold.Plus(x.q.coeffs().data(), negative_step.data(), minus.q.coeffs().data());
    numeric_delta.col(k) = (evaluate(residual, plus) - evaluate(residual, minus)) / (2 * h);

    plus = x, minus = x;
    plus.t += step, minus.t -= step;
    numeric_t.col(k) = (evaluate(residual, plus) - evaluate(residual, minus)) / (2 * h);

    plus = x, minus = x;
    plus.p += step, minus.p -= step;
    numeric_p.col(k) = (evaluate(residual, plus) - evaluate(residual, minus)) / (2 * h);
  }
  const auto expect_close = [](const Eigen::Matrix3d& analytic, const Eigen::Matrix3d& numeric,
                               const char* block) {
    const double scale = std::max(1.0, numeric.cwiseAbs().maxCoeff());
    EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-6 * scale) << block << "\nanalytic\n"
                                                                        << analytic << "\nnumeric\n"
                                                                        << numeric;
  };
  expect_close(J_delta, numeric_delta, "rotation (tangent)");
  expect_close(J_t, numeric_t, "translation");
  expect_close(J_p, numeric_p, "point");
  if (residual.dimension() == 2) {
    EXPECT_EQ(J_q.row(2).norm() + J_t.row(2).norm() + J_p.row(2).norm(), 0);
  }
}

TEST(BaResidual, JacobiansMatchCentralDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Parameters x;
    x.q = Eigen::Quaterniond(
        Eigen::AngleAxisd(M_PI * uniform(rng),
                          Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized()));
    x.t = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    // A point 1 to 5 m in front of the camera, expressed in the world.
    const Eigen::Vector3d p_c(uniform(rng), uniform(rng), 3 + 2 * uniform(rng));
    x.p = x.q.conjugate() * (p_c - x.t);
    const Eigen::Vector2d uv(320 + 100 * uniform(rng), 240 + 100 * uniform(rng));
    const double sigma = std::pow(1.2, trial % 4);
    SCOPED_TRACE(trial);
    expect_jacobians_match_central_differences(
        BaResidual(uv, 2 + uniform(rng), sigma, kIntrinsics, kBf), x);
    expect_jacobians_match_central_differences(BaResidual(uv, 0, sigma, kIntrinsics, kBf), x);
  }
}

TEST(BaResidual, PointBehindOrAtCameraFailsWithoutNanOrInf) {
  const BaResidual residual(Eigen::Vector2d(320, 240), 2, 1, kIntrinsics, kBf);
  for (const double z : {-1.0, 0.0, BaResidual::kMinDepth, std::nan("")}) {
    Parameters x;
    x.p = Eigen::Vector3d(0.1, 0.1, z);
    Eigen::Vector3d r = Eigen::Vector3d::Constant(7);
    Eigen::Matrix<double, 3, 4, Eigen::RowMajor> J_q;
    J_q.setConstant(7);
    double* jacobians[] = {J_q.data(), nullptr, nullptr};
    EXPECT_FALSE(evaluate(residual, x, r, jacobians)) << z;
    EXPECT_EQ(r, Eigen::Vector3d::Constant(7));
    EXPECT_TRUE(J_q.allFinite());
  }
  // Just in front: finite values and Jacobians.
  Parameters x;
  x.p = Eigen::Vector3d(0.1, 0.1, 2 * BaResidual::kMinDepth);
  Eigen::Vector3d r;
  Eigen::Matrix<double, 3, 4, Eigen::RowMajor> J_q;
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> J_t, J_p;
  double* jacobians[] = {J_q.data(), J_t.data(), J_p.data()};
  ASSERT_TRUE(evaluate(residual, x, r, jacobians));
  EXPECT_TRUE(r.allFinite() && J_q.allFinite() && J_t.allFinite() && J_p.allFinite());
}

}  // namespace
}  // namespace slamkit
