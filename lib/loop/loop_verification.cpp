#include "loop/loop_verification.h"

#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "loop/loop_neighbourhood.h"
#include "tracking/icp_svd_ransac.h"
#include "tracking/motion_only_ba.h"

namespace slamkit {
namespace {

std::string fewer_than(int count, const char* what, int minimum) {
  return std::to_string(count) + " " + what + ", fewer than " + std::to_string(minimum);
}

}  // namespace

LoopVerification verify_loop(const Map& map, int keyframe, int candidate,
                             const std::vector<KeypointPair>& matches, const Camera& camera,
                             const RansacSettings& ransac, const MotionBaSettings& motion_ba,
                             const LoopSettings& settings) {
  const Keyframe& query = map.keyframe(keyframe);
  const Keyframe& other = map.keyframe(candidate);
  LoopVerification result;
  result.T_keyframe_candidate_estimated = query.T_c_w * other.T_w_c;

  // Pairs: the candidate's map point in the candidate's camera, the keyframe's keypoint
  // back-projected from its depth.
  std::vector<Eigen::Vector3d> q_candidate, q_keyframe;
  std::vector<int> keypoint_of_pair, point_of_pair;
  for (const KeypointPair& m : matches) {
    const float depth = query.depths[size_t(m.keyframe_keypoint)];
    const int point = other.point_ids[size_t(m.candidate_keypoint)];
    if (depth <= 0 || point < 0 || map.point(point).bad) continue;
    q_candidate.push_back(other.T_c_w * map.point(point).p_w);
    q_keyframe.push_back(camera.back_project(query.undistorted[size_t(m.keyframe_keypoint)], depth));
    keypoint_of_pair.push_back(m.keyframe_keypoint);
    point_of_pair.push_back(point);
  }
  result.matches = int(q_candidate.size());
  if (result.matches < settings.min_matches) {
    result.reason = fewer_than(result.matches, "matches", settings.min_matches);
    return result;
  }
  const RigidFit fit = icp_svd_ransac(q_candidate, q_keyframe, ransac);
  result.inliers = fit.ok() ? fit.num_inliers : 0;
  if (result.inliers < settings.min_inliers) {
    result.reason = fewer_than(result.inliers, "RANSAC inliers", settings.min_inliers);
    return result;
  }
  // fit maps the keyframe's camera into the candidate's: T_candidate_keyframe. The closed form
  // weighs every depth alike; refined on the reprojection and disparity of its inliers (the
  // tracker's motion-only BA, the candidate's camera as the world), the loop edge is as good
  // as a tracked pose (ORB-SLAM2 refines its loop transform likewise).
  std::vector<PointObservation> observations;
  for (size_t i = 0; i < fit.inliers.size(); ++i) {
    if (!fit.inliers[i]) continue;
    const int keypoint = keypoint_of_pair[i];
    observations.push_back({q_candidate[i], query.undistorted[size_t(keypoint)],
                            query.depths[size_t(keypoint)],
                            map.pyramid().scale(query.keypoints[size_t(keypoint)].octave)});
  }
  const PoseRefinement refined = motion_only_ba(observations, camera, fit.T_prev_curr, motion_ba);
  Eigen::Isometry3d T_candidate_keyframe = refined.ok ? refined.T_w_c : fit.T_prev_curr;

  // The neighbourhood check; the loop edge is then the pose refined on every match.
  std::vector<bool> taken(query.keypoints.size(), false);
  std::set<int> paired_points;
  for (size_t i = 0; i < fit.inliers.size(); ++i)
    if (fit.inliers[i]) {
      taken[size_t(keypoint_of_pair[i])] = true;
      paired_points.insert(point_of_pair[i]);
    }
  for (const LoopPointMatch& m :
       match_loop_neighbourhood(map, keyframe, candidate, other.T_w_c * T_candidate_keyframe,
                                taken, camera, settings.neighbourhood_radius,
                                settings.neighbourhood_max_distance)) {
    if (paired_points.count(m.point)) continue;
    const size_t keypoint = size_t(m.keypoint);
    observations.push_back({other.T_c_w * map.point(m.point).p_w, query.undistorted[keypoint],
                            query.depths[keypoint],
                            map.pyramid().scale(query.keypoints[keypoint].octave)});
  }
  const PoseRefinement all = motion_only_ba(observations, camera, T_candidate_keyframe, motion_ba);
  result.neighbourhood_inliers = all.ok ? all.num_inliers : 0;
  result.T_keyframe_candidate = (all.ok ? all.T_w_c : T_candidate_keyframe).inverse();
  result.pose_error = (result.T_keyframe_candidate.translation() -
                       result.T_keyframe_candidate_estimated.translation())
                          .norm();
  if (result.neighbourhood_inliers < settings.min_neighbourhood_inliers) {
    result.reason = fewer_than(result.neighbourhood_inliers, "inliers with the neighbourhood",
                               settings.min_neighbourhood_inliers);
    return result;
  }
  if (result.pose_error >= settings.max_pose_error) {
    char text[96];
    std::snprintf(text, sizeof text, "pose %.2f m from the estimate, kappa %.2f m",
                  result.pose_error, settings.max_pose_error);
    result.reason = text;
    return result;
  }
  result.accepted = true;
  return result;
}

}  // namespace slamkit
