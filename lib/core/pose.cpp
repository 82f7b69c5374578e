#include "core/pose.h"

#include <Eigen/SVD>
#include <cmath>

namespace slamkit {

std::optional<Eigen::Isometry3d> pose_from_tum(const std::array<double, 7>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return std::nullopt;
  Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
  const double norm = q.norm();
  if (norm < 1e-12) return std::nullopt;
  q.coeffs() /= norm;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  return T;
}

std::array<double, 7> pose_to_tum(const Eigen::Isometry3d& T) {
  Eigen::Quaterniond q(T.rotation());
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d t = T.translation();
  return {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
}

Eigen::Isometry3d orthonormalised(const Eigen::Isometry3d& T) {
  Eigen::Isometry3d out = T;
  // The polar decomposition's rotation U V^T, the nearest one. (Isometry3d::rotation() would
  // not do: for an isometry Eigen returns linear() unchanged.)
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(T.linear(),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d V = svd.matrixV();
  if ((svd.matrixU() * V.transpose()).determinant() < 0) V.col(2) = -V.col(2);
  out.linear() = svd.matrixU() * V.transpose();
  return out;
}

double rotation_angle(const Eigen::Isometry3d& T) {
  return Eigen::AngleAxisd(T.rotation()).angle();
}

Eigen::Quaterniond quaternion_from_matrix(const Eigen::Matrix3d& R) {
  const double trace = R.trace();
  int largest = 3;  // 0..2: the diagonal element; 3: the trace
  double best = trace;
  for (int k = 0; k < 3; ++k)
    if (R(k, k) > best) best = R(k, k), largest = k;
  Eigen::Vector4d q;  // x y z w
  if (largest == 3) {
    q << R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1), 1 + trace;
  } else {
    const int i = largest, j = (i + 1) % 3, k = (j + 1) % 3;
    q(i) = 1 - trace + 2 * R(i, i);
    q(j) = R(j, i) + R(i, j);
    q(k) = R(k, i) + R(i, k);
    q(3) = R(k, j) - R(j, k);
  }
  q /= q.norm();
  return Eigen::Quaterniond(q(3), q(0), q(1), q(2));
}

}  // namespace slamkit
