#include "optimization/reprojection_residual.h"

namespace slamkit {

ReprojectionResidual::ReprojectionResidual(const Eigen::Vector3d& p_w, const Eigen::Vector2d& uv,
                                           double depth, double sigma, const ResidualIntrinsics& k)
    : p_w_(p_w), uv_(uv), disparity_(depth > 0 ? k.bf / depth : 0), inv_sigma_(1 / sigma), k_(k) {}

bool ReprojectionResidual::evaluate(const Eigen::Matrix3d& R_c_w, const Eigen::Vector3d& t_c_w,
                                    Vector& r, const Eigen::Matrix3d& left_jacobian,
                                    Jacobian* jacobian) const {
  const Eigen::Vector3d rotated = R_c_w * p_w_;
  const Eigen::Vector3d p_c = rotated + t_c_w;
  if (!(p_c.z() > 0)) return false;
  const double inv_z = 1 / p_c.z();
  r(0) = (k_.fx * p_c.x() * inv_z + k_.cx - uv_.x()) * inv_sigma_;
  r(1) = (k_.fy * p_c.y() * inv_z + k_.cy - uv_.y()) * inv_sigma_;
  r(2) = disparity_ > 0 ? (k_.bf * inv_z - disparity_) * inv_sigma_ : 0;
  if (!jacobian) return true;

  // d r / d p_c: the pinhole projection (and the disparity) over sigma.
  Eigen::Matrix3d d_p = Eigen::Matrix3d::Zero();
  d_p(0, 0) = k_.fx * inv_z;
  d_p(0, 2) = -k_.fx * p_c.x() * inv_z * inv_z;
  d_p(1, 1) = k_.fy * inv_z;
  d_p(1, 2) = -k_.fy * p_c.y() * inv_z * inv_z;
  if (disparity_ > 0) d_p(2, 2) = -k_.bf * inv_z * inv_z;
  d_p *= inv_sigma_;
  // d p_c / d w = -[R p_w]x J_l(w) (exp(w + dw) ~ exp(J_l dw) exp(w)); d p_c / d v = I.
  Eigen::Matrix3d minus_cross;
  minus_cross << 0, rotated.z(), -rotated.y(), -rotated.z(), 0, rotated.x(), rotated.y(),
      -rotated.x(), 0;
  jacobian->leftCols<3>() = d_p * minus_cross * left_jacobian;
  jacobian->rightCols<3>() = d_p;
  return true;
}

}  // namespace slamkit
