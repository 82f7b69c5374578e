#pragma once
// The geometric checks a loop candidate must pass (the paper's numbers,
// docs/method.md#loop-closing): ORB matches of the keyframe with the candidate's map points
// (fewer than 50: no loop), their relative pose by RANSAC-SVD on the 3D-3D pairs (the
// tracker's solver), then that pose against the current estimate: a loop only if they differ
// by less than kappa = 1 m, which rejects places that look alike but are elsewhere. Every
// number is reported so that loops.csv can show why a candidate was kept or refused.
#include <Eigen/Geometry>
#include <string>

#include <vector>

#include "core/camera.h"
#include "core/settings/loop_settings.h"
#include "core/settings/tracking_settings.h"
#include "map/map.h"

namespace slamkit {

// A descriptor match between a keypoint of the keyframe and one of the candidate.
struct KeypointPair {
  int keyframe_keypoint;
  int candidate_keypoint;
};

struct LoopVerification {
  int matches = 0;  // matches usable in 3D: depth at the keyframe's, a map point at the other
  int inliers = 0;
  // Inliers of the pose refined on the RANSAC inliers and the matches of the candidate's
  // neighbourhood projected with it.
  int neighbourhood_inliers = 0;
  // The candidate's pose in the keyframe's frame: measured (valid when inliers were found) and
  // as the map currently has it; pose_error is the distance between their translations.
  Eigen::Isometry3d T_keyframe_candidate = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_keyframe_candidate_estimated = Eigen::Isometry3d::Identity();
  double pose_error = 0;
  bool accepted = false;
  std::string reason;  // why not accepted ("" when accepted)
};

// Checks the candidate `candidate` for a loop with `keyframe` (both keyframes of `map`), given
// their descriptor matches (settings: min_matches, min_inliers, max_pose_error); the RANSAC
// pose is refined on its inliers by the motion-only BA (motion_ba).
LoopVerification verify_loop(const Map& map, int keyframe, int candidate,
                             const std::vector<KeypointPair>& matches, const Camera& camera,
                             const RansacSettings& ransac, const MotionBaSettings& motion_ba,
                             const LoopSettings& settings);

}  // namespace slamkit
