#pragma once
// What local and global BA share: a BaProblem's parameters in Ceres' layout, one residual per
// observation, Levenberg-Marquardt runs over the observations currently taken as inliers, the
// chi-square classification and the write-back. Each schedule (local_bundle_adjustment.cpp,
// global_bundle_adjustment.cpp) is a few calls on this.
#include <ceres/loss_function.h>
#include <ceres/manifold.h>

#include <deque>
#include <vector>

#include "core/stopwatch.h"
#include "optimization/ba_residual.h"
#include "optimization/bundle_adjustment.h"
#include "optimization/motion_ba_objective.h"

namespace slamkit {

class BaSolver {
 public:
  // Copies the parameters out of `problem`, and reads its observations where they are (on a
  // long map they are tens of MB): `problem` must outlive the solver. At the
  // start every observation whose point is in front of its camera is an inlier (ORB-SLAM2
  // starts with every edge; one behind the camera cannot be evaluated). Throws
  // std::invalid_argument when an observation names a pose or point that does not exist or
  // pose_fixed does not match T_c_w.
  BaSolver(const BaProblem& problem, const BaIntrinsics& intrinsics,
           const BaResidualSettings& residual);
  // The residuals point at the solver's intrinsics and the Problems at its residuals.
  BaSolver(const BaSolver&) = delete;
  BaSolver& operator=(const BaSolver&) = delete;

  // Something to optimise: at least one free pose and one observation.
  bool solvable() const;

  // Up to `iterations` LM iterations over the inlier observations, with the Huber kernel when
  // `robust`. With `points_free` the points move too (Schur on the points); otherwise the
  // points are constant and only observations of free poses take part. False when Ceres
  // failed (the parameters are then those before the call).
  bool run(int iterations, bool robust, bool points_free);

  // `iterations` LM iterations that are iterations first .. first + iterations - 1 of a
  // schedule whose points are held fixed from iteration `fix_points_after` on (paper; < 0 =
  // never): run() with the points free up to there, then with them held.
  bool run_stage(int first, int iterations, bool robust, int fix_points_after);

  // Re-tests the inliers at the current parameters: one stays an inlier when its point is in
  // front of the camera and chi2 <= chi2_2d / chi2_3d. An outlier stays out (as in ORB-SLAM2,
  // whose excluded edges keep failing on their stale chi2), so the last run's observations are
  // exactly the final inliers plus those this test rejects after it.
  void classify();

  // Iterations run, costs of the first and last run, outlier = not an inlier now.
  BaReport report() const;

  // Free poses (rotation orthonormal) and all points into `problem`; fixed poses untouched.
  void write_back(BaProblem& problem) const;

 private:
  double* rotation(int pose) { return &parameters_[7 * pose]; }
  double* translation(int pose) { return &parameters_[7 * pose + 4]; }
  double* point(int index) { return &parameters_[7 * num_poses_ + 3 * index]; }
  const double* rotation(int pose) const { return &parameters_[7 * pose]; }
  const double* translation(int pose) const { return &parameters_[7 * pose + 4]; }
  const double* point(int index) const { return &parameters_[7 * num_poses_ + 3 * index]; }
  // run() with the points held: every free pose on its own.
  bool run_poses_alone(int iterations, bool robust);
  // The observation's chi2 at the current parameters; false when it cannot be evaluated.
  bool chi2(int observation, double& value) const;

  const std::vector<BaObservation>& observations_;  // problem.observations, not a copy
  std::vector<bool> pose_fixed_;
  int num_poses_;
  int num_points_;
  // One array: per pose the Eigen quaternion (x, y, z, w) of R_c_w and t_c_w, then per point
  // p_w. Ceres orders the blocks of an elimination group by address, so with a single array
  // that order is the index order whatever the heap does, and results are bit-reproducible.
  std::vector<double> parameters_;
  // A deque, not a vector: residuals can be neither copied nor moved (Ceres' CostFunction), and
  // a deque builds them in place in blocks, without an allocation each.
  std::deque<BaResidual> residuals_;
  std::vector<bool> inlier_;
  BaIntrinsics intrinsics_;
  BaResidualSettings settings_;
  // Shared by every residual block and Problem: the Problems do not take ownership.
  ceres::HuberLoss huber_2d_;
  ceres::HuberLoss huber_3d_;
  ceres::EigenQuaternionManifold quaternion_manifold_;

  int iterations_ = 0;
  bool has_run_ = false;
  double initial_cost_ = 0;
  double final_cost_ = 0;
};

// What every schedule shares: an unsolvable problem (no free pose or no observation) is left
// unchanged; `schedule(solver)` runs the phases and says whether they all succeeded; then the
// final outlier classification, the write-back and the report.
template <class Schedule>
BaReport solve_with_schedule(BaProblem& problem, const BaIntrinsics& intrinsics,
                             const BaResidualSettings& residual, Schedule&& schedule) {
  Stopwatch stopwatch;
  BaSolver solver(problem, intrinsics, residual);
  BaReport report;
  report.outlier.assign(problem.observations.size(), false);
  if (!solver.solvable() || !schedule(solver)) return report;
  solver.classify();
  solver.write_back(problem);
  report = solver.report();
  report.seconds = stopwatch.lap() * 1e-3;
  return report;
}

}  // namespace slamkit
