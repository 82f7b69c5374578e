#include "optimization/ba_residual.h"

#include <ceres/manifold.h>

#include <Eigen/Geometry>

namespace slamkit {

BaResidual::BaResidual(const Eigen::Vector2d& uv, double depth, double sigma, const BaIntrinsics& k,
                       double bf)
    : uv_(uv), disparity_(depth > 0 ? bf / depth : 0.0), inv_sigma_(1.0 / sigma), k_(k), bf_(bf) {}

bool BaResidual::Evaluate(double const* const* parameters, double* residuals,
                          double** jacobians) const {
  const Eigen::Map<const Eigen::Quaterniond> q(parameters[0]);
  const Eigen::Map<const Eigen::Vector3d> t(parameters[1]);
  const Eigen::Map<const Eigen::Vector3d> p_w(parameters[2]);
  const Eigen::Matrix3d R = q.toRotationMatrix();
  const Eigen::Vector3d Rp = R * p_w;
  const Eigen::Vector3d p_c = Rp + t;
  // The negated test also rejects NaN.
  if (!(p_c.z() > kMinDepth) || !p_c.allFinite()) return false;

  const double inv_z = 1.0 / p_c.z();
  const double x = p_c.x() * inv_z;
  const double y = p_c.y() * inv_z;
  residuals[0] = (uv_.x() - (k_.fx * x + k_.cx)) * inv_sigma_;
  residuals[1] = (uv_.y() - (k_.fy * y + k_.cy)) * inv_sigma_;
  residuals[2] = disparity_ > 0 ? (disparity_ - bf_ * inv_z) * inv_sigma_ : 0.0;
  if (jacobians == nullptr) return true;

  // d r / d p_c: every block's Jacobian is this times d p_c / d(block).
  const double s = inv_sigma_ * inv_z;
  Eigen::Matrix3d J_pc;
  J_pc << -k_.fx * s, 0, k_.fx * x * s,  //
      0, -k_.fy * s, k_.fy * y * s,      //
      0, 0, disparity_ > 0 ? bf_ * inv_z * s : 0.0;

  using Jacobian3x3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
  if (jacobians[0] != nullptr) {
    // p_c(delta) = exp(2 delta) R p_w + t, so d p_c / d delta = -2 [R p_w]_x.
    Eigen::Matrix3d skew;
    skew << 0, -Rp.z(), Rp.y(),  //
        Rp.z(), 0, -Rp.x(),      //
        -Rp.y(), Rp.x(), 0;
    const Eigen::Matrix3d J_delta = -2.0 * J_pc * skew;
    Eigen::Matrix<double, 4, 3, Eigen::RowMajor> P;
    ceres::EigenQuaternionManifold().PlusJacobian(parameters[0], P.data());
    Eigen::Map<Eigen::Matrix<double, 3, 4, Eigen::RowMajor>> J_q(jacobians[0]);
    J_q = J_delta * P.transpose();
  }
  if (jacobians[1] != nullptr) {
    Eigen::Map<Jacobian3x3> J_t(jacobians[1]);
    J_t = J_pc;
  }
  if (jacobians[2] != nullptr) {
    Eigen::Map<Jacobian3x3> J_p(jacobians[2]);
    J_p = J_pc * R;
  }
  return true;
}

}  // namespace slamkit
