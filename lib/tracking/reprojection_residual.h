#pragma once
// Ceres residual of one matched point against the camera pose T_c_w, parameterised as an
// Eigen quaternion (x, y, z, w; EigenQuaternionManifold) and a translation. Divided by the
// observation's standard deviation, so its squared norm is the chi-square statistic.
#include <Eigen/Geometry>

namespace slamkit {

struct ResidualIntrinsics {
  double fx, fy, cx, cy;
  double bf;  // virtual baseline times fx, pixels x metres (3D residual only)
};

// kDim = 2: pixel (u, v). kDim = 3: plus the virtual-stereo disparity bf / z (ORB-SLAM2's
// RGB-D u_right term, decoupled from u): its error bf dz / z^2 grows with z^2 like the
// Kinect's depth noise, so one sigma serves all three residuals.
template <int kDim>
struct ReprojectionResidual {
  static_assert(kDim == 2 || kDim == 3, "pixel, or pixel and disparity");

  ReprojectionResidual(const Eigen::Vector3d& p_w, const Eigen::Vector2d& uv, double depth,
                       double sigma, const ResidualIntrinsics& k)
      : p_w_(p_w),
        uv_(uv),
        disparity_(kDim == 3 ? k.bf / depth : 0),
        inv_sigma_(1 / sigma),
        k_(k) {}

  template <typename T>
  bool operator()(const T* q_c_w, const T* t_c_w, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q(q_c_w);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t(t_c_w);
    const Eigen::Matrix<T, 3, 1> p_c = q * p_w_.cast<T>() + t;
    if (!(p_c.z() > T(0))) return false;  // behind the camera: no projection
    const T inv_z = T(1) / p_c.z();
    residual[0] = (T(k_.fx) * p_c.x() * inv_z + T(k_.cx) - T(uv_.x())) * T(inv_sigma_);
    residual[1] = (T(k_.fy) * p_c.y() * inv_z + T(k_.cy) - T(uv_.y())) * T(inv_sigma_);
    if constexpr (kDim == 3) residual[2] = (T(k_.bf) * inv_z - T(disparity_)) * T(inv_sigma_);
    return true;
  }

 private:
  Eigen::Vector3d p_w_;
  Eigen::Vector2d uv_;
  double disparity_;  // observed bf / depth
  double inv_sigma_;
  ResidualIntrinsics k_;
};

}  // namespace slamkit
