#pragma once
// One matched point's residual against the camera pose T_c_w = (R, t), divided by the
// observation's standard deviation, so its squared norm is the chi-square statistic; with the
// analytic Jacobian for the pose increment the motion-only BA solves for.
#include <Eigen/Core>

namespace slamkit {

struct ResidualIntrinsics {
  double fx, fy, cx, cy;
  double bf;  // virtual baseline times fx, pixels x metres (3D residual only)
};

// dimension() = 2: pixel (u, v). 3: plus the virtual-stereo disparity bf / z (ORB-SLAM2's
// RGB-D u_right term, decoupled from u): its error bf dz / z^2 grows with z^2 like the Kinect's
// depth noise, so one sigma serves all three residuals.
class ReprojectionResidual {
 public:
  using Vector = Eigen::Vector3d;                // the first dimension() entries are used
  using Jacobian = Eigen::Matrix<double, 3, 6>;  // likewise its first dimension() rows

  // depth <= 0: no depth, the 2D residual.
  ReprojectionResidual(const Eigen::Vector3d& p_w, const Eigen::Vector2d& uv, double depth,
                       double sigma, const ResidualIntrinsics& k);

  int dimension() const { return disparity_ > 0 ? 3 : 2; }

  // The residual at the pose (R_c_w, t_c_w); false (r untouched) when the point is not in
  // front of the camera. With `jacobian`, also d r / d(w, v) for the increment
  // R = exp(w) R_0, t = t_0 + v at the current w, whose SO(3) left Jacobian is `left_jacobian`
  // (the identity at w = 0).
  bool evaluate(const Eigen::Matrix3d& R_c_w, const Eigen::Vector3d& t_c_w, Vector& r,
                const Eigen::Matrix3d& left_jacobian = Eigen::Matrix3d::Identity(),
                Jacobian* jacobian = nullptr) const;

 private:
  Eigen::Vector3d p_w_;
  Eigen::Vector2d uv_;
  double disparity_;  // observed bf / depth; 0 without depth
  double inv_sigma_;
  ResidualIntrinsics k_;
};

}  // namespace slamkit
