#include "optimization/motion_ba_objective.h"

#include <ceres/rotation.h>

#include <cmath>

namespace slamkit {
namespace {

constexpr double kBehindCamera = 1e6;  // residual of a point behind the camera: the step fails

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& w) {
  Eigen::Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

}  // namespace

Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& w) {
  const double theta2 = w.squaredNorm();
  const Eigen::Matrix3d W = cross_matrix(w);
  if (theta2 < 1e-10) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 6;  // Taylor
  const double theta = std::sqrt(theta2);
  return Eigen::Matrix3d::Identity() + (1 - std::cos(theta)) / theta2 * W +
         (theta - std::sin(theta)) / (theta2 * theta) * W * W;
}

MotionBaObjective::MotionBaObjective(std::vector<Term> terms, const Eigen::Matrix3d& R_0,
                                     const Eigen::Vector3d& t_0)
    : terms_(std::move(terms)), R_0_(R_0), t_0_(t_0) {
  for (const Term& term : terms_) num_residuals_ += term.residual->dimension();
}

void MotionBaObjective::pose_at(const double* x, Eigen::Matrix3d& R_c_w,
                                Eigen::Vector3d& t_c_w) const {
  Eigen::Matrix3d exp_w;
  ceres::AngleAxisToRotationMatrix(x, exp_w.data());  // column-major, as Eigen's default
  R_c_w = exp_w * R_0_;
  t_c_w = t_0_ + Eigen::Vector3d(x[3], x[4], x[5]);
}

bool MotionBaObjective::operator()(const double* x, double* residuals, double* jacobian) const {
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
  pose_at(x, R, t);
  const Eigen::Matrix3d left_jacobian = so3_left_jacobian(Eigen::Vector3d(x[0], x[1], x[2]));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6>> J(jacobian, jacobian ? num_residuals_ : 0,
                                                         6);
  bool all_in_front = true;
  int row = 0;
  for (const Term& term : terms_) {
    const int dim = term.residual->dimension();
    ReprojectionResidual::Vector r;
    ReprojectionResidual::Jacobian d_r;
    if (!term.residual->evaluate(R, t, r, left_jacobian, jacobian ? &d_r : nullptr)) {
      all_in_front = false;
      for (int i = 0; i < dim; ++i) residuals[row + i] = kBehindCamera;
      if (jacobian) J.middleRows(row, dim).setZero();
      row += dim;
      continue;
    }
    // Without depth the third row of r and d_r is zero, so full 3-row algebra serves both.
    const double s = r.squaredNorm(), delta = term.huber_delta;
    if (delta > 0 && s > delta * delta) {
      // rho(s) = 2 delta sqrt(s) - delta^2; residual a(s) r with a = sqrt(rho / s), whose
      // Jacobian is a J + 2 a'(s) r r^T J.
      const double root = std::sqrt(s);
      const double a = std::sqrt((2 * delta * root - delta * delta) / s);
      const double da = (-delta / (s * root) + delta * delta / (s * s)) / (2 * a);
      if (jacobian) {
        const Eigen::Matrix<double, 1, 6> rt_J = r.transpose() * d_r;
        d_r = a * d_r + 2 * da * r * rt_J;
      }
      r *= a;
    }
    for (int i = 0; i < dim; ++i) residuals[row + i] = r(i);
    if (jacobian) J.middleRows(row, dim) = d_r.topRows(dim);
    row += dim;
  }
  return all_in_front;
}

}  // namespace slamkit
