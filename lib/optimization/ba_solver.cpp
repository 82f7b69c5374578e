#include "optimization/ba_solver.h"

#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <ceres/tiny_solver.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace slamkit {
namespace {

// Schur elimination groups: the points are eliminated (Ceres' heuristics would choose them
// too; stating it keeps the reduced system on the poses).
constexpr int kEliminatedGroup = 0;
constexpr int kReducedGroup = 1;
// Up to this many free poses the reduced camera system (6 per pose) is factorised densely.
// In a room every keyframe sees most others, so that system is nearly dense anyway. Measured:
// a local window's costs well under a millisecond, less than SPARSE_SCHUR's symbolic analysis
// (2.6 against 8-10 ms per Solve); a global BA iteration on synthetic loop 600 (96 keyframes)
// 0.08 s against 0.19 s by ITERATIVE_SCHUR, desk 600 (187) 0.25 against 0.29 s. Beyond, the
// dense factorisation grows as n^3 and conjugate gradients win where the problem is well
// conditioned: desk 2000 (627 keyframes, one room) 24.4 s against 20.4 s for the whole global
// BA. Through several rooms they converge slowly: long 2000 (416 keyframes) 9.0 s dense
// against 39.6 s, same ATE.
constexpr int kMaxDenseSchurPoses = 500;
// The scheduled iterations (as ORB-SLAM2's g2o runs them) unless the solve has converged to
// rounding: Ceres' default relative cost change of 1e-6 ended the whole-map BA after 4 of
// its 20 iterations with 15% more pose error; 1e-10 stops only where nothing moves any more
// (no measurable change in the tests) and saves a third of the time of a typical window.
// Deterministic either way: one thread gives bit-identical costs, hence the same stop.
constexpr double kFunctionTolerance = 1e-10;

ceres::Solver::Options solver_options(int iterations) {
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.max_num_iterations = iterations;
  options.function_tolerance = kFunctionTolerance;
  options.gradient_tolerance = 0;
  options.parameter_tolerance = 0;
  // One thread: Ceres' multi-threaded evaluation and Schur elimination sum in a
  // thread-dependent order, so only this is bit-reproducible.
  options.num_threads = 1;
  options.minimizer_progress_to_stdout = false;
  options.logging_type = ceres::SILENT;
  return options;
}

}  // namespace

BaSolver::BaSolver(const BaProblem& problem, const BaIntrinsics& intrinsics,
                   const BaResidualSettings& residual)
    : observations_(problem.observations),
      pose_fixed_(problem.pose_fixed),
      num_poses_(static_cast<int>(problem.T_c_w.size())),
      num_points_(static_cast<int>(problem.p_w.size())),
      parameters_(7 * num_poses_ + 3 * num_points_),
      intrinsics_(intrinsics),
      settings_(residual),
      huber_2d_(std::sqrt(residual.chi2_2d)),
      huber_3d_(std::sqrt(residual.chi2_3d)) {
  if (static_cast<int>(pose_fixed_.size()) != num_poses_) {
    throw std::invalid_argument("bundle adjustment: pose_fixed has " +
                                std::to_string(pose_fixed_.size()) + " entries for " +
                                std::to_string(num_poses_) + " poses");
  }
  for (int i = 0; i < num_poses_; ++i) {
    const Eigen::Quaterniond q(problem.T_c_w[i].linear());
    Eigen::Map<Eigen::Quaterniond>(rotation(i)) = q.normalized();
    Eigen::Map<Eigen::Vector3d>(translation(i)) = problem.T_c_w[i].translation();
  }
  for (int i = 0; i < num_points_; ++i) Eigen::Map<Eigen::Vector3d>(point(i)) = problem.p_w[i];

  for (const BaObservation& o : observations_) {
    if (o.pose < 0 || o.pose >= num_poses_ || o.point < 0 || o.point >= num_points_) {
      throw std::invalid_argument("bundle adjustment: observation of pose " +
                                  std::to_string(o.pose) + ", point " + std::to_string(o.point) +
                                  " out of range");
    }
    const double depth = residual.use_depth ? o.depth : 0.0;
    residuals_.emplace_back(o.uv, depth, o.sigma, intrinsics_, residual.virtual_bf);
  }
  inlier_.resize(observations_.size());
  double unused;
  for (size_t i = 0; i < observations_.size(); ++i) inlier_[i] = chi2(static_cast<int>(i), unused);
}

bool BaSolver::solvable() const {
  if (observations_.empty()) return false;
  for (bool fixed : pose_fixed_) {
    if (!fixed) return true;
  }
  return false;
}

bool BaSolver::run(int iterations, bool robust, bool points_free) {
  if (iterations <= 0) return true;
  if (!points_free) return run_poses_alone(iterations, robust);
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  // Every block is added exactly once below; the checks would cost a hash lookup per block.
  problem_options.disable_all_safety_checks = true;
  ceres::Problem problem(problem_options);
  auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();

  // A free point needs two observations or a depth: one pixel alone leaves it free along its
  // ray, which lets LM take huge steps there (through the camera) and slows everything else,
  // while it cannot move any pose at the optimum. Such points sit this run out.
  std::vector<bool> point_determined(num_points_, false);
  std::vector<bool> seen(num_points_);
  for (size_t i = 0; i < observations_.size(); ++i) {
    if (!inlier_[i]) continue;
    const int j = observations_[i].point;
    point_determined[j] = point_determined[j] || seen[j] || residuals_[i].dimension() == 3;
    seen[j] = true;
  }

  // Blocks enter the problem with their first residual: a point whose observations are all
  // outliers is not in it at all.
  std::vector<bool> pose_added(pose_fixed_.size()), point_added(num_points_);
  int free_poses = 0;
  for (size_t i = 0; i < observations_.size(); ++i) {
    const BaObservation& o = observations_[i];
    if (!inlier_[i] || !point_determined[o.point]) continue;
    ceres::LossFunction* loss = nullptr;
    if (robust) loss = residuals_[i].dimension() == 3 ? &huber_3d_ : &huber_2d_;
    problem.AddResidualBlock(&residuals_[i], loss, rotation(o.pose), translation(o.pose),
                             point(o.point));
    if (!pose_added[o.pose]) {
      pose_added[o.pose] = true;
      problem.SetManifold(rotation(o.pose), &quaternion_manifold_);
      if (pose_fixed_[o.pose]) {
        problem.SetParameterBlockConstant(rotation(o.pose));
        problem.SetParameterBlockConstant(translation(o.pose));
      } else {
        ++free_poses;
      }
      ordering->AddElementToGroup(rotation(o.pose), kReducedGroup);
      ordering->AddElementToGroup(translation(o.pose), kReducedGroup);
    }
    if (!point_added[o.point]) {
      point_added[o.point] = true;
      ordering->AddElementToGroup(point(o.point), kEliminatedGroup);
    }
  }
  if (problem.NumResidualBlocks() == 0) return true;

  ceres::Solver::Options options = solver_options(iterations);
  // Larger problems: conjugate gradients on the reduced system, preconditioned by its
  // diagonal blocks; a sparse Cholesky of the nearly dense system was slower still (synthetic
  // desk 600, 189 keyframes: 7.5 s with SPARSE_SCHUR, 4.4 s with this, same ATE).
  options.linear_solver_type =
      free_poses <= kMaxDenseSchurPoses ? ceres::DENSE_SCHUR : ceres::ITERATIVE_SCHUR;
  options.preconditioner_type = ceres::SCHUR_JACOBI;
  options.linear_solver_ordering = ordering;
  ceres::Solver::Summary summary;
  const std::vector<double> before = parameters_;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) {
    parameters_ = before;
    return false;
  }
  if (!has_run_) initial_cost_ = summary.initial_cost;
  has_run_ = true;
  final_cost_ = summary.final_cost;
  // One linear solve per LM iteration; summary.iterations misses one that ends on the tolerance.
  iterations_ += summary.num_linear_solves;
  return true;
}

bool BaSolver::run_stage(int first, int iterations, bool robust, int fix_points_after) {
  const int with_points =
      fix_points_after < 0 ? iterations : std::clamp(fix_points_after - first, 0, iterations);
  return run(with_points, robust, true) && run(iterations - with_points, robust, false);
}

bool BaSolver::run_poses_alone(int iterations, bool robust) {
  // With the points held, each free pose's observations involve that pose alone: the problem
  // is one independent 6-dof problem per pose, each solved by ceres::TinySolver (dense LM on
  // the exact Huber cost, as the tracker's motion-only BA). One sparse ceres::Solve over all of
  // them spent most of its time building and preprocessing the problem (measured: 0.25 of the
  // 0.55 s a keyframe window took on synthetic desk 600). Poses are solved in index order.
  const ResidualIntrinsics k{intrinsics_.fx, intrinsics_.fy, intrinsics_.cx, intrinsics_.cy,
                             settings_.virtual_bf};
  std::vector<std::vector<int>> by_pose(static_cast<size_t>(num_poses_));
  for (size_t i = 0; i < observations_.size(); ++i)
    if (inlier_[i] && !pose_fixed_[observations_[i].pose])
      by_pose[size_t(observations_[i].pose)].push_back(int(i));
  double initial_cost = 0, final_cost = 0;
  int most_iterations = 0;
  bool any = false;
  for (int pose = 0; pose < num_poses_; ++pose) {
    const std::vector<int>& mine = by_pose[size_t(pose)];
    if (mine.empty()) continue;
    std::vector<ReprojectionResidual> residuals;
    residuals.reserve(mine.size());
    for (int i : mine) {
      const BaObservation& o = observations_[size_t(i)];
      const double depth = settings_.use_depth ? o.depth : 0.0;
      residuals.emplace_back(Eigen::Map<const Eigen::Vector3d>(point(o.point)), o.uv, depth,
                             o.sigma, k);
    }
    std::vector<MotionBaObjective::Term> terms;
    for (const ReprojectionResidual& r : residuals) {
      const double chi2 = r.dimension() == 3 ? settings_.chi2_3d : settings_.chi2_2d;
      terms.push_back({&r, robust ? std::sqrt(chi2) : 0.0});
    }
    Eigen::Map<Eigen::Quaterniond> q(rotation(pose));
    Eigen::Map<Eigen::Vector3d> t(translation(pose));
    const MotionBaObjective objective(std::move(terms), q.toRotationMatrix(), t);
    Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
    Eigen::VectorXd r0(objective.NumResiduals());
    if (!objective(x.data(), r0.data(), nullptr)) continue;  // a point behind: leave the pose
    ceres::TinySolver<MotionBaObjective> solver;
    solver.options.max_num_iterations = iterations;
    solver.options.function_tolerance = kFunctionTolerance * r0.squaredNorm();
    solver.options.gradient_tolerance = 0;
    solver.options.parameter_tolerance = 0;
    const auto summary = solver.Solve(objective, &x);
    if (!x.allFinite()) return false;
    Eigen::Matrix3d R;
    Eigen::Vector3d t_new;
    objective.pose_at(x.data(), R, t_new);
    q = Eigen::Quaterniond(R).normalized();
    t = t_new;
    initial_cost += summary.initial_cost;
    final_cost += summary.final_cost;
    most_iterations = std::max(most_iterations, summary.iterations);
    any = true;
  }
  if (!any) return true;
  if (!has_run_) initial_cost_ = initial_cost;
  has_run_ = true;
  final_cost_ = final_cost;
  iterations_ += most_iterations;
  return true;
}

bool BaSolver::chi2(int observation, double& value) const {
  const BaObservation& o = observations_[observation];
  const double* parameters[] = {rotation(o.pose), translation(o.pose), point(o.point)};
  Eigen::Vector3d r;
  if (!residuals_[observation].Evaluate(parameters, r.data(), nullptr)) return false;
  value = r.squaredNorm();
  return true;
}

void BaSolver::classify() {
  for (size_t i = 0; i < observations_.size(); ++i) {
    if (!inlier_[i]) continue;
    const double threshold =
        residuals_[i].dimension() == 3 ? settings_.chi2_3d : settings_.chi2_2d;
    double value;
    inlier_[i] = chi2(static_cast<int>(i), value) && value <= threshold;
  }
}

BaReport BaSolver::report() const {
  BaReport report;
  report.solved = true;
  report.iterations = iterations_;
  report.initial_cost = initial_cost_;
  report.final_cost = final_cost_;
  report.outlier.resize(inlier_.size());
  for (size_t i = 0; i < inlier_.size(); ++i) {
    report.outlier[i] = !inlier_[i];
    report.num_outliers += report.outlier[i];
  }
  return report;
}

void BaSolver::write_back(BaProblem& problem) const {
  for (size_t i = 0; i < problem.T_c_w.size(); ++i) {
    if (pose_fixed_[i]) continue;
    const int pose = static_cast<int>(i);
    const Eigen::Quaterniond q = Eigen::Map<const Eigen::Quaterniond>(rotation(pose)).normalized();
    problem.T_c_w[i].linear() = q.toRotationMatrix();
    problem.T_c_w[i].translation() = Eigen::Map<const Eigen::Vector3d>(translation(pose));
  }
  for (size_t i = 0; i < problem.p_w.size(); ++i) {
    problem.p_w[i] = Eigen::Map<const Eigen::Vector3d>(point(static_cast<int>(i)));
  }
}

}  // namespace slamkit
