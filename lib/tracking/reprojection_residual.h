#pragma once
// Ceres residual of one matched point against the camera pose T_c_w, parameterised as an
// Eigen quaternion (x, y, z, w; EigenQuaternionManifold) and a translation. Divided by the
// observation's standard deviation, so its squared norm is the chi-square statistic.
// Analytic Jacobians: automatic differentiation cost 2-3x more per frame for the same numbers.
#include <ceres/sized_cost_function.h>

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
class ReprojectionResidual : public ceres::SizedCostFunction<kDim, 4, 3> {
  static_assert(kDim == 2 || kDim == 3, "pixel, or pixel and disparity");

 public:
  ReprojectionResidual(const Eigen::Vector3d& p_w, const Eigen::Vector2d& uv, double depth,
                       double sigma, const ResidualIntrinsics& k)
      : p_w_(p_w),
        uv_(uv),
        disparity_(kDim == 3 ? k.bf / depth : 0),
        inv_sigma_(1 / sigma),
        k_(k) {}

  bool Evaluate(double const* const* parameters, double* r, double** jacobians) const override {
    return evaluate_at(parameters[0], parameters[1], r, jacobians ? jacobians[0] : nullptr,
                       jacobians ? jacobians[1] : nullptr);
  }

 private:
  // Ceres stores Jacobians row-major.
  template <int kCols>
  using Jacobian = Eigen::Matrix<double, kDim, kCols, Eigen::RowMajor>;

  bool evaluate_at(const double* q_c_w, const double* t_c_w, double* r, double* d_q,
                   double* d_t) const {
    const double w = q_c_w[3];
    const Eigen::Map<const Eigen::Vector3d> v(q_c_w), t(t_c_w);
    // Eigen's q * p for any q, which the derivative below differentiates exactly:
    // R(q) p = p + 2 w (v x p) + 2 v x (v x p).
    const Eigen::Vector3d v_x_p = v.cross(p_w_);
    const Eigen::Vector3d p_c = p_w_ + 2 * w * v_x_p + 2 * v.cross(v_x_p) + t;
    if (!(p_c.z() > 0)) return false;
    const double inv_z = 1 / p_c.z();
    r[0] = (k_.fx * p_c.x() * inv_z + k_.cx - uv_.x()) * inv_sigma_;
    r[1] = (k_.fy * p_c.y() * inv_z + k_.cy - uv_.y()) * inv_sigma_;
    if constexpr (kDim == 3) r[2] = (k_.bf * inv_z - disparity_) * inv_sigma_;
    if (!d_q && !d_t) return true;

    // d r / d p_c: the pinhole projection (and the disparity) over sigma.
    Jacobian<3> d_p = Jacobian<3>::Zero();
    d_p(0, 0) = k_.fx * inv_z;
    d_p(0, 2) = -k_.fx * p_c.x() * inv_z * inv_z;
    d_p(1, 1) = k_.fy * inv_z;
    d_p(1, 2) = -k_.fy * p_c.y() * inv_z * inv_z;
    if constexpr (kDim == 3) d_p(2, 2) = -k_.bf * inv_z * inv_z;
    d_p *= inv_sigma_;
    if (d_t) Eigen::Map<Jacobian<3>>{d_t} = d_p;
    if (d_q) {
      // d p_c / d(x, y, z): 2 w [-p]x + 2 ((v.p) I + v p^T - 2 p v^T); d p_c / d w: 2 v x p.
      Eigen::Matrix<double, 3, 4> d_rot;
      const Eigen::Vector3d& p = p_w_;
      Eigen::Matrix3d minus_p_cross;
      minus_p_cross << 0, p.z(), -p.y(), -p.z(), 0, p.x(), p.y(), -p.x(), 0;
      d_rot.leftCols<3>() = 2 * w * minus_p_cross + 2 * (v.dot(p) * Eigen::Matrix3d::Identity() +
                                                         v * p.transpose() - 2 * p * v.transpose());
      d_rot.col(3) = 2 * v_x_p;
      Eigen::Map<Jacobian<4>>{d_q} = d_p * d_rot;
    }
    return true;
  }

  Eigen::Vector3d p_w_;
  Eigen::Vector2d uv_;
  double disparity_;  // observed bf / depth
  double inv_sigma_;
  ResidualIntrinsics k_;
};

}  // namespace slamkit
