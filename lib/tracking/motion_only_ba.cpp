#include "tracking/motion_only_ba.h"

#include <ceres/tiny_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "optimization/motion_ba_objective.h"
#include "optimization/reprojection_residual.h"

namespace slamkit {
namespace {

constexpr int kMinObservations = 3;  // a pose has 6 dof; fewer points cannot fix it

}  // namespace

PoseRefinement motion_only_ba(const std::vector<PointObservation>& observations,
                              const Camera& camera, const Eigen::Isometry3d& T_w_c_guess,
                              const MotionBaSettings& settings) {
  const int n = static_cast<int>(observations.size());
  const Eigen::Isometry3d T_c_w_guess = T_w_c_guess.inverse();
  Eigen::Matrix3d R_c_w = T_c_w_guess.linear();
  Eigen::Vector3d t_c_w = T_c_w_guess.translation();
  const ResidualIntrinsics k{camera.fx, camera.fy, camera.cx, camera.cy, settings.virtual_bf};
  // Observations with depth get the disparity residual too (and the 3-dof chi-square test).
  std::vector<ReprojectionResidual> residuals;
  residuals.reserve(n);
  for (const PointObservation& o : observations) {
    const bool with_depth = settings.use_depth && camera.is_valid_depth(o.depth);
    residuals.emplace_back(o.p_w, o.uv, with_depth ? o.depth : 0.0, o.sigma, k);
  }
  const auto chi2_threshold = [&](int i) {
    return residuals[i].dimension() == 3 ? settings.chi2_3d : settings.chi2_2d;
  };

  // Classifies every observation, outliers included, so that one can come back.
  std::vector<bool> inliers(n);
  auto classify = [&]() {
    int count = 0;
    for (int i = 0; i < n; ++i) {
      ReprojectionResidual::Vector r;
      inliers[i] = residuals[i].evaluate(R_c_w, t_c_w, r) && r.squaredNorm() < chi2_threshold(i);
      count += inliers[i];
    }
    return count;
  };
  // Before the first round every point in front of the camera takes part (ORB-SLAM2 starts
  // with all matches as inliers).
  int num_inliers = 0;
  for (int i = 0; i < n; ++i) {
    inliers[i] = (T_c_w_guess * observations[i].p_w).z() > 0;
    num_inliers += inliers[i];
  }

  // ceres::TinySolver, Ceres' dense Levenberg-Marquardt for a few parameters: one call returns
  // every residual and the whole Jacobian. The general ceres::Solve took 4-5 ms per frame on
  // ~700 matches, mostly its per-residual-block bookkeeping. Single-threaded: deterministic.
  ceres::TinySolver<MotionBaObjective> solver;
  solver.options.max_num_iterations = settings.iterations_per_round;
  bool solved = true;
  for (int round = 0; round < settings.rounds && num_inliers >= kMinObservations; ++round) {
    const bool robust = round < settings.robust_rounds;
    std::vector<MotionBaObjective::Term> terms;
    for (int i = 0; i < n; ++i) {
      if (inliers[i]) terms.push_back({&residuals[i], robust ? std::sqrt(chi2_threshold(i)) : 0});
    }
    const MotionBaObjective objective(std::move(terms), R_c_w, t_c_w);
    Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
    // Stop when the cost changes by less than a millionth of itself (Ceres' default).
    Eigen::VectorXd r0(objective.NumResiduals());
    objective(x.data(), r0.data(), nullptr);
    solver.options.function_tolerance = 1e-6 * r0.squaredNorm();
    solver.Solve(objective, &x);
    solved = x.allFinite();
    if (!solved) break;
    objective.pose_at(x.data(), R_c_w, t_c_w);
    num_inliers = classify();
  }

  PoseRefinement result;
  Eigen::Isometry3d T_c_w = Eigen::Isometry3d::Identity();
  T_c_w.linear() = R_c_w;
  T_c_w.translation() = t_c_w;
  result.T_w_c = T_c_w.inverse();
  result.inliers = std::move(inliers);
  result.num_inliers = num_inliers;
  result.ok = solved && num_inliers >= std::max(settings.min_inliers, kMinObservations);
  return result;
}

}  // namespace slamkit
