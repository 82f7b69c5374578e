#pragma once
// One observation's bundle-adjustment residual: the world point p_w moved into the camera by
// T_c_w = (q, t), pinhole-projected and compared with the measured undistorted keypoint, plus,
// with depth, the virtual-stereo disparity bf / z (ORB-SLAM2's RGB-D u_right term, decoupled
// from u). Every entry is measured minus predicted, divided by the keypoint's sigma, so the
// squared norm is the chi-square statistic.
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>

#include "optimization/bundle_adjustment.h"

namespace slamkit {

// Parameter blocks, in this order:
//   q: rotation R_c_w as Eigen quaternion coefficients (x, y, z, w), unit norm, on
//      ceres::EigenQuaternionManifold. Its tangent delta updates R <- exp(2 delta) R (Ceres'
//      convention: delta is half the rotation vector, applied on the left).
//   t: translation t_c_w, 3 values.
//   p: world point p_w, 3 values.
// Always 3 residuals so that every row block has the same size (Ceres then runs its
// specialised 3x3x3 Schur eliminator); without depth the third is identically zero, which
// leaves the cost and the minimiser of the 2D residual unchanged.
// The Jacobians are analytic. The one for q is the tangent-space Jacobian mapped back through
// the manifold's PlusJacobian P (orthonormal columns for a unit quaternion): J_q = J_delta P^T,
// which is the derivative of r(q / |q|) at unit q, so J_q P = J_delta as Ceres needs.
class BaResidual final : public ceres::SizedCostFunction<3, 4, 3, 3> {
 public:
  // Points at most this far in front of the camera (metres) cannot be projected: Evaluate
  // fails instead of returning inf or NaN, and the observation counts as an outlier.
  static constexpr double kMinDepth = 1e-3;

  // depth <= 0: no depth, the 2D residual. bf: virtual baseline times fx (pixels x metres).
  // `k` is referenced, not copied (a global BA holds one residual per observation): it must
  // outlive the residual.
  BaResidual(const Eigen::Vector2d& uv, double depth, double sigma, const BaIntrinsics& k,
             double bf);

  // 2 (pixel) or 3 (pixel and disparity): the degrees of freedom of the chi-square test.
  int dimension() const { return disparity_ > 0 ? 3 : 2; }

  // False, with residuals and Jacobians untouched, when the point is not in front of the
  // camera (z <= kMinDepth or not finite); Ceres then rejects the step that led there.
  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  Eigen::Vector2d uv_;
  double disparity_;  // measured bf / depth; 0 without depth
  double inv_sigma_;
  const BaIntrinsics& k_;
  double bf_;
};

}  // namespace slamkit
