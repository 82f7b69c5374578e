#pragma once
// Bundle adjustment over keyframe poses and map points
// (docs/method.md#local-mapping-and-bundle-adjustment), as plain data so that local BA, global
// BA and the tests build the same problem. The map (lib/map) is turned into a BaProblem by the
// mapping stage and the result written back; this module knows nothing of the map.
#include <Eigen/Geometry>
#include <vector>

#include "core/settings/optimization_settings.h"

namespace slamkit {

struct BaIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

struct BaObservation {
  int pose = -1;                                 // index into BaProblem::T_c_w
  int point = -1;                                // index into BaProblem::p_w
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();  // undistorted keypoint, pixels
  double depth = 0;  // measured depth at the keypoint, metres; <= 0 = none (2D residual)
  double sigma = 1;  // keypoint standard deviation, pixels (scale_factor^octave)
};

struct BaProblem {
  std::vector<Eigen::Isometry3d> T_c_w;  // camera-from-world per pose
  std::vector<bool> pose_fixed;          // same size as T_c_w
  std::vector<Eigen::Vector3d> p_w;      // world points
  std::vector<BaObservation> observations;
};

struct BaReport {
  bool solved = false;  // false: nothing to optimise (or Ceres failed); input unchanged
  // LM iterations run over all phases; fewer than scheduled when a phase converged (an
  // iteration changed the cost by at most 1e-10 of itself).
  int iterations = 0;
  // Ceres cost at the start of the first phase (with the kernel, if robust) and at the end of
  // the last (over the observations it kept): 0.5 sum of chi2 (or of the Huber of it).
  double initial_cost = 0;
  double final_cost = 0;
  // Per observation: failed the chi-square test (chi2_2d / chi2_3d) or had its point behind
  // the camera, after the robust stage (then left out of the rest, as ORB-SLAM2 does) or at the
  // end. Without a robust stage (global BA, robust = false) only the final test counts.
  std::vector<bool> outlier;
  int num_outliers = 0;
  double seconds = 0;
};

// Local BA schedule (ORB-SLAM2's LocalBundleAdjustment): robust_iterations with Huber, then
// observations failing the chi-square test (or behind the camera) are dropped and the solve
// repeated for refine_iterations without the kernel; points held fixed after
// fix_points_after_iterations (paper). Updates problem.T_c_w and problem.p_w in place.
// Single-threaded: the result is the same at any thread count, bit for bit from run to run.
// No shared state: concurrent calls on different problems are safe.
BaReport local_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                 const BaResidualSettings& residual,
                                 const LocalBaSettings& settings);

// Global BA: every pose and point (the caller fixes the first keyframe), iterations of LM,
// robust with an outlier pass when settings.robust; points held fixed after
// fix_points_after_iterations, as in local BA.
BaReport global_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                  const BaResidualSettings& residual,
                                  const GlobalBaSettings& settings);

}  // namespace slamkit
