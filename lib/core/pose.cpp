#include "core/pose.h"

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
  out.linear() = Eigen::Quaterniond(T.linear()).normalized().toRotationMatrix();
  return out;
}

double rotation_angle(const Eigen::Isometry3d& T) {
  return Eigen::AngleAxisd(T.rotation()).angle();
}

}  // namespace slamkit
