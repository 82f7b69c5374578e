#pragma once
// Motion-only bundle adjustment (docs/method.md#matching-and-pose): the current pose refined
// on the reprojection error of its matched points, with outliers re-classified between rounds
// as ORB-SLAM2's PoseOptimization does.
#include <Eigen/Geometry>
#include <vector>

#include "core/camera.h"
#include "core/settings/tracking_settings.h"

namespace slamkit {

struct PointObservation {
  Eigen::Vector3d p_w = Eigen::Vector3d::Zero();  // the matched point, world frame
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();   // its keypoint, undistorted pixels
  // Measured depth at the keypoint, metres; 0 or outside the camera's valid range = none
  // (2D residual only).
  double depth = 0;
  double sigma = 1;  // keypoint standard deviation, pixels (ORB: scale_factor^octave)
};

struct PoseRefinement {
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  std::vector<bool> inliers;  // one per observation, by the chi-square test of the last round
  int num_inliers = 0;
  bool ok = false;  // solved, with at least settings.min_inliers inliers
};

// Refines the camera pose T_w_c from an initial guess: ceres::TinySolver (Levenberg-Marquardt),
// single-threaded, so the result is deterministic; Huber kernel with delta = sqrt(chi2
// threshold) in the robust rounds.
PoseRefinement motion_only_ba(const std::vector<PointObservation>& observations,
                              const Camera& camera, const Eigen::Isometry3d& T_w_c_guess,
                              const MotionBaSettings& settings);

}  // namespace slamkit
