#pragma once
// The geometric checks a loop candidate must pass (SPEC section 5, the paper's numbers): ORB
// matches between the keyframe and the candidate's map points (fewer than 50: no loop), their
// relative pose by RANSAC-SVD on the 3D-3D pairs (the tracker's solver), then that pose against
// the current estimate: a loop only if they differ by less than kappa = 1 m, which rejects
// places that look alike but are elsewhere. Every number is reported so that loops.csv can
// show why a candidate was kept or refused.
#include <Eigen/Geometry>
#include <string>

#include "core/camera.h"
#include "core/settings/matcher_settings.h"
#include "core/settings/tracking_settings.h"
#include "map/map.h"

namespace slamkit {

struct LoopCheckSettings {
  int min_matches = 50;        // (paper) fewer ORB matches with the candidate: no loop
  int min_inliers = 20;        // (ORB-SLAM2) RANSAC inliers of the relative pose
  double max_pose_error = 1.0;  // (paper) kappa, metres: measured against estimated pose
};

struct LoopVerification {
  int matches = 0;  // descriptor matches with the candidate's map points, both with 3D
  int inliers = 0;
  // The candidate's pose in the keyframe's frame: measured (valid when inliers were found) and
  // as the map currently has it; pose_error is the distance between their translations.
  Eigen::Isometry3d T_keyframe_candidate = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_keyframe_candidate_estimated = Eigen::Isometry3d::Identity();
  double pose_error = 0;
  bool accepted = false;
  std::string reason;  // why not accepted ("" when accepted)
};

// Checks the candidate `candidate` for a loop with `keyframe` (both keyframes of `map`).
LoopVerification verify_loop(const Map& map, int keyframe, int candidate, const Camera& camera,
                             const MatcherSettings& matcher, const RansacSettings& ransac,
                             const LoopCheckSettings& settings);

}  // namespace slamkit
