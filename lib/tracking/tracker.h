#pragma once
// The front end's state and its per-frame recipe (docs/method.md#matching-and-pose and
// docs/method.md#keyframes). Each step is a solver function of its own (tracking/*.h); this
// class chooses between them and keeps what must persist from frame to frame: the recent poses
// and the keyframe codes. It reads the map (the local map is the covisible keyframes' points)
// and counts which points it saw; the back end (lib/mapping) inserts the keyframes it asks for.
#include <map>
#include <vector>

#include "core/camera.h"
#include "core/settings/settings.h"
#include "core/stopwatch.h"
#include "core/trajectory.h"
#include "map/map.h"
#include "tracking/motion_model.h"
#include "tracking/photometric_equations.h"
#include "tracking/prepared_frame.h"
#include "tracking/surface_pyramid.h"
#include "tracking/tracked_frame.h"

namespace slamkit {

class Tracker {
 public:
  struct Match {
    int point_id;  // map point
    int keypoint;  // keypoint of the current frame
  };

  Tracker(const Camera& camera, const Settings& settings, Map& map);

  // Tracks the next frame (frames must come in order) and returns what happened. When the
  // record says keyframe, the caller inserts keyframe_from(frame, record) into the map before
  // the next frame. The frame's keypoints are moved to its colour stamp when the camera's
  // exposure timing asks for it (tracking/exposure_unrolling.h).
  TrackedFrame track(PreparedFrame& frame);

  // The keyframe the frame makes: its features and pose, its keypoints linked to the points
  // tracking matched (the inliers of the last track() call).
  Keyframe keyframe_from(const PreparedFrame& frame, const TrackedFrame& record) const;

 private:
  struct PoseEstimate {
    Eigen::Isometry3d T_w_c;
    std::vector<Match> inliers;  // matches consistent with the pose
    bool ok = false;
    int support = 0;  // what the failure check weighs: inlier matches or dense pairs
    std::string failure;
    SurfacePyramid surfaces;  // the frame's, when dense alignment built them
    GreyPyramid grey;         // likewise, when it weighed grey levels too
  };

  // Matches the frame, solves, refines and checks its pose (the failure check); the lap
  // times go into the record.
  PoseEstimate attempt(PreparedFrame& frame, TrackedFrame& record, Stopwatch& watch);
  Eigen::Isometry3d predict_pose(double stamp) const;
  // The keyframes observing the voters' points, most of them first (then lowest index).
  std::vector<int> keyframes_by_votes(const std::vector<Match>& voters) const;
  // keyframes_by_votes of the last frame's inliers.
  std::vector<int> voted_keyframes() const;
  std::vector<int> local_keyframes(const std::vector<int>& voted) const;
  // The points of the voted keyframes' neighbourhood (local_keyframes) matched by projection
  // from the pose guess.
  std::vector<Match> match_local_map(const PreparedFrame& frame,
                                     const Eigen::Isometry3d& T_w_c_guess,
                                     const std::vector<int>& voted);
  std::vector<Match> match_keyframe(const PreparedFrame& frame, const Keyframe& keyframe) const;
  std::vector<Match> match_for_relocalisation(const PreparedFrame& frame) const;
  // The matches of a frame after a lost one; guess becomes the pose they were searched from.
  std::vector<Match> relocalise(const PreparedFrame& frame, Eigen::Isometry3d& guess);
  bool accept(const PreparedFrame& frame, PoseEstimate& estimate, const TrackedFrame& record) const;
  PoseEstimate estimate_pose(const PreparedFrame& frame, const std::vector<Match>& matches,
                             const Eigen::Isometry3d& T_w_c_guess, TrackedFrame& record) const;
  PoseEstimate align_svd_ransac(const PreparedFrame& frame, const std::vector<Match>& matches,
                                const Eigen::Isometry3d& T_w_c_guess) const;
  PoseEstimate align_point_to_plane(const PreparedFrame& frame, const std::vector<Match>& matches,
                                    const Eigen::Isometry3d& T_w_c_guess) const;
  void refine_pose(const PreparedFrame& frame, PoseEstimate& estimate, TrackedFrame& record) const;
  // The inliers as frame refinement keeps them (TrackedFrame::matched).
  std::vector<MatchedKeypoint> matched_keypoints(const PreparedFrame& frame,
                                                 const std::vector<Match>& inliers) const;
  // The second pass: the frame unrolled with the velocity into it, which the refined pose now
  // gives, and refined again (the first keyframe too, at frame 1).
  void refine_unrolled(PreparedFrame& frame, PoseEstimate& estimate, TrackedFrame& record);
  Eigen::Isometry3d motion_model_pose(double stamp) const;
  // Moves the frame's keypoints, as the preparation found them, to its colour stamp along
  // velocity v (velocity_between) at pose T_w_c. False, and nothing moved, for instant timing.
  bool unroll_exposure(PreparedFrame& frame, const StampedVelocity& v,
                       const Eigen::Isometry3d& T_w_c);
  // The first keyframe was made before any velocity was known: once the second frame gives
  // one, its keypoints and the points they made are moved as unroll_exposure moves a frame's,
  // so that the map does not mix skewed and unskewed views. True if anything moved.
  bool unroll_first_keyframe(const StampedVelocity& v);
  // The depth image's instant minus the colour stamp, when the camera trusts depth stamps.
  double depth_offset(const PreparedFrame& frame) const;
  void choose_keyframe(const PreparedFrame& frame, TrackedFrame& record);
  // Counts the inliers as found, and takes the keyframe sharing most of them as reference.
  void settle_inliers(const std::vector<Match>& inliers, TrackedFrame& record);
  // The depth image resampled to pinhole geometry (unchanged for undistorted cameras).
  cv::Mat pinhole_depth(const cv::Mat& depth) const;
  // The grey image likewise (bilinear: intensities, unlike depths, may be blended).
  cv::Mat pinhole_grey(const cv::Mat& grey) const;

  Camera camera_;
  Settings settings_;
  Map& map_;
  std::vector<Match> inliers_;        // of the last tracked frame
  int reference_keyframe_ = -1;       // the keyframe sharing most points with the last frame
  std::vector<int> voted_keyframes_;  // keyframes_by_votes() of the last frame...
  size_t voted_at_keyframes_ = 0;     // ...counted when the map had this many keyframes
  std::vector<size_t> point_mark_;    // per map point: last frame that listed it (local map)
  std::vector<StampedPose> poses_;    // every tracked frame, in order
  StampedPose last_tracked_;          // the last frame that was not lost
  std::map<size_t, WindowCode> window_codes_;  // recent frames' codes, by frame index
  cv::Mat previous_depth_;                     // as recorded, for dense alignment
  double previous_depth_offset_ = 0;           // its stamp minus the previous colour stamp
  cv::Mat previous_grey_;                      // level 0 of the ORB pyramid, for dense alignment
  SurfacePyramid previous_surfaces_;   // the previous frame's, if dense alignment built them
  GreyPyramid previous_grey_pyramid_;  // likewise
  bool previous_lost_ = false;
  // This frame is matched without a prediction: after a lost frame, or when tracking with the
  // prediction failed.
  bool reacquiring_ = false;
  bool velocity_known_ = false;  // the last two frames were tracked, not lost or re-acquired
  cv::Mat undistort_map_x_, undistort_map_y_;  // depth remap for distorted cameras
  // The current frame's keypoints as prepared, before unroll_exposure moved them.
  size_t seen_frame_ = size_t(-1);
  std::vector<Eigen::Vector2d> seen_undistorted_;
  std::vector<float> seen_depths_;
  // The first keyframe's, likewise: unroll_first_keyframe may run twice at frame 1 (once per
  // attempt) and must move them once, by the last velocity.
  std::vector<Eigen::Vector2d> first_seen_undistorted_;
  std::vector<float> first_seen_depths_;
};

}  // namespace slamkit
