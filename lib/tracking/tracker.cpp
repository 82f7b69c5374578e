#include "tracking/tracker.h"

#include <algorithm>
#include <map>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/pose.h"
#include "core/stopwatch.h"
#include "features/descriptor.h"
#include "features/descriptor_matcher.h"
#include "features/keypoint_grid.h"
#include "features/projection_matcher.h"
#include "keyframes/keyframe_rule.h"
#include "tracking/exposure_unrolling.h"
#include "tracking/failure_check.h"
#include "tracking/icp_svd_ransac.h"
#include "tracking/motion_model.h"
#include "tracking/motion_only_ba.h"
#include "tracking/point_to_plane.h"

namespace slamkit {
namespace {

// The matches whose keypoint has a depth: the 3D-3D pairs the closed form can use.
template <class Match>
int pairs_with_depth(const PreparedFrame& frame, const std::vector<Match>& matches) {
  return int(std::count_if(matches.begin(), matches.end(), [&](const Match& m) {
    return frame.keypoint_depths[size_t(m.keypoint)] > 0;
  }));
}

// A keypoint as motion-only BA measures it; the caller puts in its matched point.
PointObservation keypoint_observation(const PreparedFrame& frame, int keypoint) {
  const size_t k = size_t(keypoint);
  const int octave = frame.features.keypoints[k].octave;
  return {Eigen::Vector3d::Zero(), frame.features.undistorted[k], frame.keypoint_depths[k],
          frame.features.pyramid.scales[size_t(octave)]};
}

}  // namespace

Tracker::Tracker(const Camera& camera, const Settings& settings, Map& map)
    : camera_(camera), settings_(settings), map_(map) {
  if (!camera_.distortion.is_zero()) {
    // Dense alignment works in pinhole geometry; the recorded depth is in the lens's.
    const cv::Matx33d K(camera_.fx, 0, camera_.cx, 0, camera_.fy, camera_.cy, 0, 0, 1);
    const cv::Matx<double, 1, 5> d(camera_.distortion.k1, camera_.distortion.k2,
                                   camera_.distortion.p1, camera_.distortion.p2,
                                   camera_.distortion.k3);
    cv::initUndistortRectifyMap(K, d, cv::noArray(), K, {camera_.width, camera_.height}, CV_32FC1,
                                undistort_map_x_, undistort_map_y_);
  }
}

TrackedFrame Tracker::track(PreparedFrame& frame) {
  TrackedFrame record;
  record.index = frame.index;
  record.stamp = frame.stamp;
  record.features = int(frame.features.size());
  window_codes_[frame.index] = frame.window_code;

  if (poses_.empty()) {  // the first frame defines the world frame and the first keyframe
    record.keyframe = true;
    first_seen_undistorted_ = frame.features.undistorted;
    first_seen_depths_ = frame.keypoint_depths;
    inliers_.clear();
    voted_keyframes_.clear();
  } else {
    Stopwatch watch;
    reacquiring_ = previous_lost_;
    PoseEstimate estimate = attempt(frame, record, watch);
    // ORB-SLAM2 tracks with the reference keyframe when its motion model fails: here the frame
    // is re-acquired against the map at once, as the frame after a lost one would be.
    if (!estimate.ok && !reacquiring_) {
      reacquiring_ = true;
      PoseEstimate second = attempt(frame, record, watch);
      // The record now holds the second attempt's matches and solver, so its outcome is the
      // one kept, failed or not. The frame's surfaces and grey pyramid are the same whichever
      // attempt built them; the next frame reuses them.
      if (second.surfaces.empty()) second.surfaces = std::move(estimate.surfaces);
      if (second.grey.empty()) second.grey = std::move(estimate.grey);
      estimate = std::move(second);
    }
    if (!estimate.ok) {
      record.lost = true;
      record.failure = estimate.failure;
      record.solver = PoseSolver::kMotionModel;
      estimate.T_w_c = motion_model_pose(frame.stamp);
    }
    record.T_w_c = orthonormalised(estimate.T_w_c);
    record.inliers = int(estimate.inliers.size());
    settle_inliers(record.lost ? std::vector<Match>{} : estimate.inliers, record);
    previous_surfaces_ = std::move(estimate.surfaces);
    previous_grey_pyramid_ = std::move(estimate.grey);
    // A re-acquired frame was matched to one keyframe, not the local map: its pose is the
    // least reliable, and a keyframe made from it would carry that into the map.
    if (!record.lost && !reacquiring_) choose_keyframe(frame, record);
    if (settings_.optimization.refine_frames && record.refined && !record.lost && !record.keyframe)
      record.matched = matched_keypoints(frame, estimate.inliers);
    record.keyframe_ms = watch.lap();
  }
  poses_.push_back({frame.stamp, record.T_w_c});
  if (!record.lost) last_tracked_ = poses_.back();
  previous_depth_ = frame.depth;
  previous_depth_offset_ = depth_offset(frame);
  previous_grey_ = frame.features.pyramid.levels[0];
  velocity_known_ = !record.lost && !previous_lost_;
  previous_lost_ = record.lost;
  return record;
}

Tracker::PoseEstimate Tracker::attempt(PreparedFrame& frame, TrackedFrame& record,
                                       Stopwatch& watch) {
  record.refined = false;
  Eigen::Isometry3d guess = predict_pose(frame.stamp);
  // The constant-velocity model's velocity, for matching and the solvers (none at frame 1).
  if (!reacquiring_ && velocity_known_ && poses_.size() >= 2)
    unroll_exposure(frame, velocity_between(poses_[poses_.size() - 2], poses_.back()), guess);
  // Re-acquiring, the prediction cannot be trusted: match without it.
  std::vector<Match> matches = reacquiring_ ? relocalise(frame, guess)
                                            : match_local_map(frame, guess, voted_keyframes());
  record.matches = int(matches.size());
  record.match_ms += watch.lap();

  PoseEstimate estimate = estimate_pose(frame, matches, guess, record);
  record.pose_ms += watch.lap();
  if (estimate.ok) refine_pose(frame, estimate, record);
  if (estimate.ok && record.refined) refine_unrolled(frame, estimate, record);
  record.refine_ms += watch.lap();
  if (estimate.ok) estimate.ok = accept(frame, estimate, record);
  return estimate;
}

Eigen::Isometry3d Tracker::predict_pose(double stamp) const {
  // The velocity is only known between two frames that were both tracked: a lost frame's
  // pose is the model's own guess, and a re-acquired one jumps by the correction.
  if (poses_.size() < 2 || !velocity_known_) return poses_.back().T_w_c;
  return predict_constant_velocity(poses_[poses_.size() - 2], poses_.back(), stamp);
}

std::vector<int> Tracker::keyframes_by_votes(const std::vector<Match>& voters) const {
  std::map<int, int> votes;
  for (const Match& m : voters)
    for (const Observation& o : map_.point(m.point_id).observations) ++votes[o.keyframe];
  std::vector<std::pair<int, int>> ranked;  // (-votes, keyframe)
  for (const auto& [k, count] : votes) ranked.push_back({-count, k});
  std::sort(ranked.begin(), ranked.end());
  std::vector<int> keyframes;
  for (const auto& [negative_votes, k] : ranked) keyframes.push_back(k);
  return keyframes;
}

std::vector<int> Tracker::voted_keyframes() const {
  // The votes counted for the last frame stand unless a keyframe came in since (its insertion
  // changes the observations).
  return voted_at_keyframes_ == map_.keyframes().size() ? voted_keyframes_
                                                         : keyframes_by_votes(inliers_);
}

std::vector<int> Tracker::local_keyframes(const std::vector<int>& voted) const {
  // ORB-SLAM2's UpdateLocalKeyFrames: the keyframes that observe the matched points, most
  // shared first, then their best covisible neighbours, up to the setting's count.
  const size_t limit = size_t(std::max(1, settings_.mapping.local_map_keyframes));
  std::vector<int> local;
  auto add = [&](int k) {
    if (local.size() < limit && std::find(local.begin(), local.end(), k) == local.end())
      local.push_back(k);
  };
  add(int(map_.keyframes().size()) - 1);  // the latest keyframe's fresh points, always
  for (int k : voted) add(k);
  for (size_t i = 0; i < local.size() && local.size() < limit; ++i)
    for (int k : map_.best_covisible(local[i], int(limit))) add(k);
  return local;
}

std::vector<Tracker::Match> Tracker::match_local_map(const PreparedFrame& frame,
                                                     const Eigen::Isometry3d& T_w_c_guess,
                                                     const std::vector<int>& voted) {
  // The local map's points that the predicted view can see (ORB-SLAM2's isInFrustum: in front,
  // in the image, within the scale-valid distances, seen within 60 deg of their mean view),
  // each searched at the pyramid level its distance predicts.
  const Eigen::Isometry3d T_c_w = T_w_c_guess.inverse();
  const Eigen::Vector3d centre = T_w_c_guess.translation();
  point_mark_.resize(size_t(map_.num_point_ids()), size_t(-1));
  std::vector<int> ids;
  MapPointSet points;
  for (int k : local_keyframes(voted))
    for (int id : map_.keyframe(k).point_ids) {
      if (id < 0 || point_mark_[size_t(id)] == frame.index) continue;
      point_mark_[size_t(id)] = frame.index;
      const MapPoint& p = map_.point(id);
      if (p.bad) continue;
      const Eigen::Vector3d p_c = T_c_w * p.p_w;
      if (p_c.z() <= 0 || !camera_.contains(camera_.project(p_c))) continue;
      const Eigen::Vector3d ray = p.p_w - centre;
      const double distance = ray.norm();
      if (distance < 0.8 * p.min_distance || distance > 1.2 * p.max_distance) continue;
      if (ray.dot(p.normal) < settings_.mapping.min_view_cos * distance * p.normal.norm()) continue;
      map_.count_visible(id);
      ids.push_back(id);
      points.points_w.push_back(p.p_w);
      points.octaves.push_back(map_.predict_octave(p, distance));
    }
  points.descriptors.create(int(ids.size()), kDescriptorBytes, CV_8U);
  for (size_t k = 0; k < ids.size(); ++k)
    std::copy_n(map_.point(ids[k]).descriptor.data(), kDescriptorBytes,
                points.descriptors.ptr<uchar>(int(k)));
  const KeypointGrid grid(frame.features.undistorted, settings_.matcher.grid_cell_size);
  MatcherSettings matcher = settings_.matcher;
  // After a failure the prediction is poor: search a wider window (ORB-SLAM2 widens too).
  if (reacquiring_) matcher.projection_radius *= settings_.tracking.lost_search_radius_factor;
  std::vector<Match> matches;
  for (const ProjectionMatch& m :
       match_by_projection(points, T_w_c_guess, camera_, frame.features, grid, matcher))
    matches.push_back({ids[size_t(m.point)], m.keypoint});
  if (int(matches.size()) >= settings_.tracking.min_pairs_for_svd) return matches;

  // Too few for the closed form: add descriptor matches against the latest keyframe, which
  // need no pose prior. Keypoints already matched by projection keep their match.
  std::vector<bool> taken(frame.features.size(), false);
  for (const Match& m : matches) taken[size_t(m.keypoint)] = true;
  for (const Match& m : match_keyframe(frame, map_.keyframes().back()))
    if (!taken[size_t(m.keypoint)]) {
      taken[size_t(m.keypoint)] = true;
      matches.push_back(m);
    }
  return matches;
}

std::vector<Tracker::Match> Tracker::match_keyframe(const PreparedFrame& frame,
                                                    const Keyframe& keyframe) const {
  std::vector<Match> matches;
  if (frame.features.descriptors.empty() || keyframe.descriptors.empty()) return matches;
  for (const cv::DMatch& m :
       match_descriptors(frame.features.descriptors, keyframe.descriptors, settings_.matcher)) {
    const int id = keyframe.point_ids[size_t(m.trainIdx)];
    if (id >= 0) matches.push_back({id, m.queryIdx});
  }
  return matches;
}

std::vector<Tracker::Match> Tracker::match_for_relocalisation(const PreparedFrame& frame) const {
  // Candidates: the latest keyframe and the ones whose window code is most like the frame's.
  const auto& keyframes = map_.keyframes();
  std::vector<std::pair<double, size_t>> ranked;
  for (size_t k = 0; k + 1 < keyframes.size(); ++k)
    if (!keyframes[k].culled)  // no points left to match
      ranked.push_back({-window_similarity(frame.window_code, keyframes[k].window_code), k});
  const size_t count =
      std::min(ranked.size(), size_t(settings_.tracking.relocalisation_candidates));
  std::partial_sort(ranked.begin(), ranked.begin() + long(count), ranked.end());
  std::vector<size_t> candidates = {keyframes.size() - 1};
  for (size_t i = 0; i < count; ++i) candidates.push_back(ranked[i].second);

  std::vector<Match> best;
  for (size_t k : candidates) {
    std::vector<Match> matches = match_keyframe(frame, keyframes[k]);
    if (matches.size() > best.size()) best = std::move(matches);
  }
  return best;
}

std::vector<Tracker::Match> Tracker::relocalise(const PreparedFrame& frame,
                                                Eigen::Isometry3d& guess) {
  // ORB-SLAM2's Relocalization: descriptor matches to the candidate keyframes are often too
  // few to be judged on their own (a blurred frame matches few), but a pose from a handful
  // of them places the frame well enough to search the map around it by projection, which
  // finds the many matches the pose is then judged on. Without a seed, the matches stand.
  std::vector<Match> matches = match_for_relocalisation(frame);
  const int pairs = pairs_with_depth(frame, matches);
  if (pairs >= settings_.tracking.min_pairs_for_svd ||
      pairs < settings_.tracking.relocalisation_min_inliers)
    return matches;
  const PoseEstimate seed = align_svd_ransac(frame, matches, guess);
  if (!seed.ok || seed.support < settings_.tracking.relocalisation_min_inliers) return matches;
  guess = seed.T_w_c;
  std::vector<Match> searched = match_local_map(frame, guess, keyframes_by_votes(seed.inliers));
  return searched.size() > matches.size() ? searched : matches;
}

bool Tracker::accept(const PreparedFrame& frame, PoseEstimate& estimate,
                     const TrackedFrame& record) const {
  // Re-acquired against the map: the map vouches for the pose. After a lost frame its jump
  // from the (motion model) pose before says nothing; re-acquired in the frame whose tracking
  // failed, the pose before was tracked and the speed limits hold as for any frame.
  if (reacquiring_ && record.solver == PoseSolver::kSvdRansac) {
    if (estimate.support < settings_.tracking.min_pairs_for_svd) {
      estimate.failure = "not re-acquired: too few inliers";
      return false;
    }
    if (previous_lost_) return true;
  }
  const PoseSupport support{estimate.support, record.refined, int(estimate.inliers.size()),
                            record.matches};
  const MotionCheck check =
      check_tracking(poses_.back().T_w_c, estimate.T_w_c, frame.stamp - poses_.back().stamp,
                     support, settings_.tracking.failure);
  if (!check.ok())
    estimate.failure =
        check.failure == TrackingFailure::kTooFewInliers ? "too few inliers" : "implausible jump";
  return check.ok();
}

Tracker::PoseEstimate Tracker::estimate_pose(const PreparedFrame& frame,
                                             const std::vector<Match>& matches,
                                             const Eigen::Isometry3d& T_w_c_guess,
                                             TrackedFrame& record) const {
  record.pairs_3d = pairs_with_depth(frame, matches);
  if (record.pairs_3d >= settings_.tracking.min_pairs_for_svd) {
    record.solver = PoseSolver::kSvdRansac;
    PoseEstimate estimate = align_svd_ransac(frame, matches, T_w_c_guess);
    if (estimate.ok) return estimate;
  }
  record.solver = PoseSolver::kPointToPlane;
  return align_point_to_plane(frame, matches, T_w_c_guess);
}

Tracker::PoseEstimate Tracker::align_svd_ransac(const PreparedFrame& frame,
                                                const std::vector<Match>& matches,
                                                const Eigen::Isometry3d& T_w_c_guess) const {
  // Map points are expressed in the predicted camera, so that the RANSAC threshold sees
  // camera depths; the solved transform is then the correction of the prediction.
  const Eigen::Isometry3d T_guess_w = T_w_c_guess.inverse();
  std::vector<Eigen::Vector3d> q_guess, q_curr;
  std::vector<size_t> pair_match;
  for (size_t k = 0; k < matches.size(); ++k) {
    const float z = frame.keypoint_depths[size_t(matches[k].keypoint)];
    if (z <= 0) continue;
    q_guess.push_back(T_guess_w * map_.point(matches[k].point_id).p_w);
    q_curr.push_back(
        camera_.back_project(frame.features.undistorted[size_t(matches[k].keypoint)], z));
    pair_match.push_back(k);
  }
  const RigidFit fit = icp_svd_ransac(q_guess, q_curr, settings_.tracking.ransac);
  PoseEstimate estimate;
  if (!fit.ok()) {
    estimate.failure = "RANSAC found no consistent pose";
    return estimate;
  }
  estimate.T_w_c = T_w_c_guess * fit.T_prev_curr;
  std::vector<bool> keep(matches.size(), true);  // matches without depth go on to the BA
  for (size_t i = 0; i < pair_match.size(); ++i) keep[pair_match[i]] = fit.inliers[i];
  for (size_t k = 0; k < matches.size(); ++k)
    if (keep[k]) estimate.inliers.push_back(matches[k]);
  estimate.support = fit.num_inliers;
  estimate.ok = true;
  return estimate;
}

Tracker::PoseEstimate Tracker::align_point_to_plane(const PreparedFrame& frame,
                                                    const std::vector<Match>& matches,
                                                    const Eigen::Isometry3d& T_w_c_guess) const {
  const Eigen::Isometry3d& T_w_prev = poses_.back().T_w_c;
  // The co-visible region: the matched points as the previous frame saw them; with too few
  // of them to bound anything, the whole image.
  cv::Rect box;
  if (int(matches.size()) >= settings_.tracking.min_matches_for_box) {
    std::vector<cv::Point2f> corners;
    const Eigen::Isometry3d T_prev_w = T_w_prev.inverse();
    for (const Match& m : matches) {
      const Eigen::Vector3d p = T_prev_w * map_.point(m.point_id).p_w;
      if (p.z() <= 0) continue;
      const Eigen::Vector2d uv = camera_.project(p);
      corners.emplace_back(float(uv.x()), float(uv.y()));
    }
    if (!corners.empty())
      box = cv::boundingRect(corners) & cv::Rect(0, 0, camera_.width, camera_.height);
  }
  // Each frame's surfaces are built once: the current frame's serve again as the previous
  // ones when the next frame is aligned densely too.
  const PointToPlaneSettings& settings = settings_.tracking.point_to_plane;
  PoseEstimate estimate;
  estimate.surfaces = make_surface_pyramid(pinhole_depth(frame.depth), camera_, settings);
  SurfacePyramid built;  // only when the previous frame was not aligned densely
  if (previous_surfaces_.empty())
    built = make_surface_pyramid(pinhole_depth(previous_depth_), camera_, settings);
  const SurfacePyramid& prev = previous_surfaces_.empty() ? built : previous_surfaces_;
  GreyPyramid built_grey;  // likewise
  if (settings.photometric_weight > 0) {
    estimate.grey = make_grey_pyramid(pinhole_grey(frame.features.pyramid.levels[0]),
                                      estimate.surfaces, settings);
    if (previous_grey_pyramid_.empty())
      built_grey = make_grey_pyramid(pinhole_grey(previous_grey_), prev, settings);
  }
  const GreyPyramid& prev_grey =
      previous_grey_pyramid_.empty() ? built_grey : previous_grey_pyramid_;
  const DenseAlignment dense =
      point_to_plane(prev, estimate.surfaces, T_w_prev.inverse() * T_w_c_guess, box, settings,
                     estimate.grey.empty() ? nullptr : &prev_grey, &estimate.grey);
  estimate.T_w_c = T_w_prev * dense.T_prev_curr;
  estimate.inliers = matches;  // unchecked: the motion-only BA sorts them
  estimate.support = dense.num_correspondences;
  // Ill-conditioned but converged is accepted: the solver kept the prediction only in the
  // directions the geometry leaves free, which beats replacing the whole pose by the model.
  estimate.ok = dense.converged && dense.status != DenseAlignStatus::kTooFewCorrespondences;
  if (!estimate.ok)
    estimate.failure = dense.status == DenseAlignStatus::kTooFewCorrespondences
                           ? "dense: too few correspondences"
                           : "dense: not converged";
  return estimate;
}

void Tracker::refine_unrolled(PreparedFrame& frame, PoseEstimate& estimate,
                              TrackedFrame& record) {
  const StampedVelocity v = velocity_between(last_tracked_, {frame.stamp, estimate.T_w_c});
  const bool first_moved = poses_.size() == 1 && unroll_first_keyframe(v);
  // After a failure v is the mean velocity since the last tracked frame. Across a smooth
  // motion that is the velocity here; across a whip of the camera (kinect jerk: 12 rad/s
  // between frames moving at 0.3 rad/s) it is nothing like it. A mean above the failure
  // check's speed limits is such a case: the frame is not moved by it.
  const FailureSettings& limits = settings_.tracking.failure;
  if (reacquiring_ && (v.linear.norm() > limits.max_speed ||
                         v.angular.norm() > limits.max_angular_speed_deg * M_PI / 180))
    return;
  if (unroll_exposure(frame, v, estimate.T_w_c) || first_moved)
    refine_pose(frame, estimate, record);
}

void Tracker::refine_pose(const PreparedFrame& frame, PoseEstimate& estimate,
                          TrackedFrame& record) const {
  const MotionBaSettings& ba = settings_.tracking.motion_ba;
  const int needed = record.solver == PoseSolver::kPointToPlane
                         ? std::max(ba.min_inliers, ba.min_matches_after_dense)
                         : ba.min_inliers;
  if (int(estimate.inliers.size()) < needed) return;
  std::vector<PointObservation> observations;
  for (const Match& m : estimate.inliers) {
    observations.push_back(keypoint_observation(frame, m.keypoint));
    observations.back().p_w = map_.point(m.point_id).p_w;
  }
  const PoseRefinement refined = motion_only_ba(observations, camera_, estimate.T_w_c, ba);
  if (!refined.ok) return;  // the solver's estimate stands (dense alignment needs no points)
  record.refined = true;
  estimate.T_w_c = refined.T_w_c;
  std::vector<Match> kept;
  for (size_t i = 0; i < observations.size(); ++i)
    if (refined.inliers[i]) kept.push_back(estimate.inliers[i]);
  estimate.inliers = std::move(kept);
  if (record.solver == PoseSolver::kSvdRansac) estimate.support = refined.num_inliers;
}

std::vector<MatchedKeypoint> Tracker::matched_keypoints(const PreparedFrame& frame,
                                                        const std::vector<Match>& inliers) const {
  std::vector<MatchedKeypoint> matched;
  matched.reserve(inliers.size());
  for (const Match& m : inliers) {
    const PointObservation o = keypoint_observation(frame, m.keypoint);
    matched.push_back({m.point_id, float(o.uv.x()), float(o.uv.y()), float(o.depth),
                       float(o.sigma)});
  }
  return matched;
}

Eigen::Isometry3d Tracker::motion_model_pose(double stamp) const {
  // The paper's rule: a frame that is not a keyframe takes the mean velocities of the 2 keyframes
  // before it, each over the interval that ends at that keyframe.
  std::vector<StampedVelocity> velocities;
  const auto& keyframes = map_.keyframes();
  for (size_t k = keyframes.size(); k-- > 0 && velocities.size() < 2;) {
    const size_t i = keyframes[k].frame_index;
    if (i == 0) break;
    velocities.insert(velocities.begin(), velocity_between(poses_[i - 1], poses_[i]));
  }
  if (velocities.size() < 2) return predict_pose(stamp);
  return predict_linear_velocity(velocities[0], velocities[1], poses_.back(), stamp);
}

namespace {

// The velocity as exposure_unrolling.h takes it: both parts in the camera at rotation R_w_c.
CameraVelocity in_camera(const StampedVelocity& v, const Eigen::Matrix3d& R_w_c) {
  return {v.angular, R_w_c.transpose() * v.linear};
}

}  // namespace

bool Tracker::unroll_exposure(PreparedFrame& frame, const StampedVelocity& v,
                              const Eigen::Isometry3d& T_w_c) {
  const ExposureTiming timing{camera_.readout_time, depth_offset(frame)};
  if (!settings_.tracking.unroll_exposure || timing.is_instant()) return false;
  if (seen_frame_ != frame.index) {
    seen_frame_ = frame.index;
    seen_undistorted_ = frame.features.undistorted;
    seen_depths_ = frame.keypoint_depths;
  }
  UnrolledKeypoints unrolled =
      slamkit::unroll_exposure(frame.features.keypoints, seen_undistorted_, seen_depths_,
                               frame.depth, camera_, timing, in_camera(v, T_w_c.linear()));
  frame.features.undistorted = std::move(unrolled.undistorted);
  frame.keypoint_depths = std::move(unrolled.depths);
  return true;
}

double Tracker::depth_offset(const PreparedFrame& frame) const {
  return camera_.exact_depth_stamps ? frame.depth_stamp - frame.stamp : 0.0;
}

bool Tracker::unroll_first_keyframe(const StampedVelocity& v) {
  const ExposureTiming timing{camera_.readout_time, previous_depth_offset_};
  if (!settings_.tracking.unroll_exposure || timing.is_instant() || map_.keyframes().size() != 1)
    return false;
  const Keyframe& first = map_.keyframe(0);
  UnrolledKeypoints unrolled =
      slamkit::unroll_exposure(first.keypoints, first_seen_undistorted_, first_seen_depths_,
                               previous_depth_, camera_, timing, in_camera(v, first.T_w_c.linear()));
  for (size_t i = 0; i < first.keypoints.size(); ++i) {
    const int id = first.point_ids[i];
    if (id < 0 || unrolled.depths[i] <= 0) continue;  // depth lost: the point stays as made
    map_.set_point_position(
        id, first.T_w_c * camera_.back_project(unrolled.undistorted[i], unrolled.depths[i]));
    map_.update_point_geometry(id);
  }
  map_.set_keyframe_keypoints(0, std::move(unrolled.undistorted), std::move(unrolled.depths));
  return true;
}

void Tracker::settle_inliers(const std::vector<Match>& inliers, TrackedFrame& record) {
  inliers_ = inliers;
  for (const Match& m : inliers_) map_.count_found(m.point_id);
  voted_keyframes_ = keyframes_by_votes(inliers_);
  voted_at_keyframes_ = map_.keyframes().size();
  if (!voted_keyframes_.empty()) reference_keyframe_ = voted_keyframes_.front();
  if (reference_keyframe_ < 0) reference_keyframe_ = int(map_.keyframes().size()) - 1;
  record.reference_keyframe = reference_keyframe_;
  record.T_ref_c = map_.keyframe(reference_keyframe_).T_c_w * record.T_w_c;
}

void Tracker::choose_keyframe(const PreparedFrame& frame, TrackedFrame& record) {
  const Keyframe& latest = map_.keyframes().back();
  std::vector<const WindowCode*> compared;
  for (size_t i : keyframe_neighbours(latest.frame_index, frame.index, settings_.keyframes))
    compared.push_back(&window_codes_.at(i));
  const int reference_points = int(std::count_if(latest.point_ids.begin(), latest.point_ids.end(),
                                                 [](int id) { return id >= 0; }));
  const KeyframeDecision decision = decide_keyframe(
      frame.window_code, compared, int(inliers_.size()), reference_points, settings_.keyframes);
  record.similarity = decision.similarity;
  record.keyframe = decision.is_keyframe;
  if (!record.keyframe) return;
  // Codes older than the new keyframe's neighbours are never compared again.
  const size_t n = size_t(std::max(0, settings_.keyframes.neighbour_frames));
  window_codes_.erase(window_codes_.begin(),
                      window_codes_.lower_bound(frame.index >= n ? frame.index - n : 0));
}

Keyframe Tracker::keyframe_from(const PreparedFrame& frame, const TrackedFrame& record) const {
  Keyframe keyframe;
  keyframe.frame_index = frame.index;
  keyframe.stamp = frame.stamp;
  keyframe.T_w_c = record.T_w_c;
  keyframe.keypoints = frame.features.keypoints;
  keyframe.undistorted = frame.features.undistorted;
  keyframe.depths = frame.keypoint_depths;
  keyframe.descriptors = frame.features.descriptors;
  keyframe.point_ids.assign(frame.features.size(), -1);
  keyframe.window_code = frame.window_code;
  for (const Match& m : inliers_) keyframe.point_ids[size_t(m.keypoint)] = m.point_id;
  return keyframe;
}

cv::Mat Tracker::pinhole_grey(const cv::Mat& grey) const {
  if (undistort_map_x_.empty()) return grey;
  cv::Mat out;
  cv::remap(grey, out, undistort_map_x_, undistort_map_y_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return out;
}

cv::Mat Tracker::pinhole_depth(const cv::Mat& depth) const {
  if (undistort_map_x_.empty()) return depth;
  cv::Mat out;
  // Nearest neighbour: interpolating would blend foreground and background depths.
  cv::remap(depth, out, undistort_map_x_, undistort_map_y_, cv::INTER_NEAREST, cv::BORDER_CONSTANT,
            0);
  return out;
}

}  // namespace slamkit
