#include "tracking/motion_only_ba.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "tracking/reprojection_residual.h"

namespace slamkit {
namespace {

constexpr int kMinObservations = 3;  // a pose has 6 dof; fewer points cannot fix it

// Pose blocks of T_c_w: the point transform the projection needs, as ORB-SLAM2 optimises.
struct PoseBlocks {
  double q[4];  // Eigen order x, y, z, w
  double t[3];
};

PoseBlocks to_blocks(const Eigen::Isometry3d& T_w_c) {
  const Eigen::Isometry3d T_c_w = T_w_c.inverse();
  const Eigen::Quaterniond q = Eigen::Quaterniond(T_c_w.linear()).normalized();
  return {{q.x(), q.y(), q.z(), q.w()},
          {T_c_w.translation().x(), T_c_w.translation().y(), T_c_w.translation().z()}};
}

Eigen::Isometry3d from_blocks(const PoseBlocks& b) {
  Eigen::Isometry3d T_c_w = Eigen::Isometry3d::Identity();
  T_c_w.linear() = Eigen::Quaterniond(b.q[3], b.q[0], b.q[1], b.q[2]).normalized().matrix();
  T_c_w.translation() = Eigen::Vector3d(b.t[0], b.t[1], b.t[2]);
  return T_c_w.inverse();
}

// The chi-square statistic of one observation; infinite behind the camera.
double chi2(const ceres::CostFunction& residual, const PoseBlocks& pose) {
  const double* parameters[] = {pose.q, pose.t};
  double r[3];
  if (!residual.Evaluate(parameters, r, nullptr)) return std::numeric_limits<double>::infinity();
  double sum = 0;
  for (int i = 0; i < residual.num_residuals(); ++i) sum += r[i] * r[i];
  return sum;
}

}  // namespace

PoseRefinement motion_only_ba(const std::vector<PointObservation>& observations,
                              const Camera& camera, const Eigen::Isometry3d& T_w_c_guess,
                              const MotionBaSettings& settings) {
  const int n = static_cast<int>(observations.size());
  PoseBlocks pose = to_blocks(T_w_c_guess);
  const ResidualIntrinsics k{camera.fx, camera.fy, camera.cx, camera.cy, settings.virtual_bf};
  // Observations with depth get the disparity residual too (and the 3-dof chi-square test).
  std::vector<bool> has_depth(n);
  std::vector<std::unique_ptr<ceres::CostFunction>> residuals(n);
  for (int i = 0; i < n; ++i) {
    const PointObservation& o = observations[i];
    has_depth[i] = settings.use_depth && camera.is_valid_depth(o.depth);
    if (has_depth[i])
      residuals[i] = std::make_unique<ReprojectionResidual<3>>(o.p_w, o.uv, o.depth, o.sigma, k);
    else
      residuals[i] = std::make_unique<ReprojectionResidual<2>>(o.p_w, o.uv, o.depth, o.sigma, k);
  }

  // Classifies every observation, outliers included, so that one can come back.
  std::vector<bool> inliers(n);
  auto classify = [&]() {
    int count = 0;
    for (int i = 0; i < n; ++i) {
      inliers[i] = chi2(*residuals[i], pose) < (has_depth[i] ? settings.chi2_3d : settings.chi2_2d);
      count += inliers[i];
    }
    return count;
  };
  // Before the first round every point in front of the camera takes part (ORB-SLAM2 starts
  // with all matches as inliers).
  int num_inliers = 0;
  for (int i = 0; i < n; ++i) {
    inliers[i] = (T_w_c_guess.inverse() * observations[i].p_w).z() > 0;
    num_inliers += inliers[i];
  }

  ceres::EigenQuaternionManifold quaternion_manifold;
  ceres::HuberLoss huber_2d(std::sqrt(settings.chi2_2d)), huber_3d(std::sqrt(settings.chi2_3d));
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = settings.iterations_per_round;
  options.num_threads = 1;  // determinism
  options.logging_type = ceres::SILENT;

  bool solved = true;
  for (int round = 0; round < settings.rounds && num_inliers >= kMinObservations; ++round) {
    ceres::Problem problem(problem_options);
    problem.AddParameterBlock(pose.q, 4, &quaternion_manifold);
    problem.AddParameterBlock(pose.t, 3);
    const bool robust = round < settings.robust_rounds;
    for (int i = 0; i < n; ++i) {
      if (!inliers[i]) continue;
      ceres::LossFunction* loss = robust ? (has_depth[i] ? &huber_3d : &huber_2d) : nullptr;
      problem.AddResidualBlock(residuals[i].get(), loss, pose.q, pose.t);
    }
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    solved = summary.IsSolutionUsable();
    if (!solved) break;
    num_inliers = classify();
  }

  PoseRefinement result;
  result.T_w_c = from_blocks(pose);
  result.inliers = std::move(inliers);
  result.num_inliers = num_inliers;
  result.ok = solved && num_inliers >= std::max(settings.min_inliers, kMinObservations);
  return result;
}

}  // namespace slamkit
