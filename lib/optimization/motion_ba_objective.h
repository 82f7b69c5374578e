#pragma once
// The cost motion-only BA minimises, in the form ceres::TinySolver takes (a function of 6
// parameters returning all residuals and their Jacobian at once).
#include <Eigen/Core>
#include <vector>

#include "optimization/reprojection_residual.h"

namespace slamkit {

// Parameters x = (w, v): the pose R_c_w = exp(w) R_0, t_c_w = t_0 + v around the pose of the
// round. The cost is the sum over the terms of rho(|r_i|^2) / 2, with rho the Huber function of
// delta_i (delta_i <= 0: the plain square). TinySolver minimises a sum of squares, so each
// residual is rescaled by sqrt(rho(s) / s), s = |r_i|^2, and its Jacobian is the exact one of the
// rescaled residual: the minimum is that of the Huber cost (Ceres' loss functions do the same
// with an approximate Jacobian).
class MotionBaObjective {
 public:
  using Scalar = double;
  enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = 6 };

  struct Term {
    const ReprojectionResidual* residual;
    double huber_delta;
  };

  MotionBaObjective(std::vector<Term> terms, const Eigen::Matrix3d& R_0,
                    const Eigen::Vector3d& t_0);

  int NumResiduals() const { return num_residuals_; }

  // Residuals and, if `jacobian` is not null, their Jacobian (column-major, NumResiduals() x 6).
  // A point that falls behind the camera gets a huge residual, so TinySolver rejects the step,
  // and makes this return false.
  bool operator()(const double* x, double* residuals, double* jacobian) const;

  void pose_at(const double* x, Eigen::Matrix3d& R_c_w, Eigen::Vector3d& t_c_w) const;

 private:
  std::vector<Term> terms_;
  Eigen::Matrix3d R_0_;
  Eigen::Vector3d t_0_;
  int num_residuals_ = 0;
};

// J_l(w) of SO(3): exp(w + dw) = exp(J_l(w) dw) exp(w) to first order.
Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& w);

}  // namespace slamkit
