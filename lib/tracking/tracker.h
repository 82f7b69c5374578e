#pragma once
// The front end's state and its per-frame recipe (SPEC sections 2 and 3). Each step is a
// solver function of its own (tracking/*.h); this class chooses between them and keeps what
// must persist from frame to frame: the map, the recent poses, the keyframe codes.
#include <map>
#include <vector>

#include "core/camera.h"
#include "core/settings/settings.h"
#include "core/trajectory.h"
#include "map/map.h"
#include "tracking/prepared_frame.h"
#include "tracking/tracked_frame.h"

namespace slamkit {

class Tracker {
 public:
  Tracker(const Camera& camera, const Settings& settings);

  // Tracks the next frame (frames must come in order) and returns what happened.
  TrackedFrame track(const PreparedFrame& frame);

  const Map& map() const { return map_; }

 private:
  struct Match {
    int point_id;  // map point
    int keypoint;  // keypoint of the current frame
  };
  struct PoseEstimate {
    Eigen::Isometry3d T_w_c;
    std::vector<Match> inliers;  // matches consistent with the pose
    bool ok = false;
    int support = 0;  // what the failure check weighs: inlier matches or dense pairs
    std::string failure;
  };

  Eigen::Isometry3d predict_pose(double stamp) const;
  std::vector<Match> match_local_map(const PreparedFrame& frame,
                                     const Eigen::Isometry3d& T_w_c_guess) const;
  std::vector<Match> match_keyframe(const PreparedFrame& frame, const Keyframe& keyframe) const;
  std::vector<Match> match_for_relocalisation(const PreparedFrame& frame) const;
  bool accept(const PreparedFrame& frame, PoseEstimate& estimate, PoseSolver solver) const;
  PoseEstimate estimate_pose(const PreparedFrame& frame, const std::vector<Match>& matches,
                             const Eigen::Isometry3d& T_w_c_guess, TrackedFrame& record) const;
  PoseEstimate align_svd_ransac(const PreparedFrame& frame, const std::vector<Match>& matches,
                                const Eigen::Isometry3d& T_w_c_guess) const;
  PoseEstimate align_point_to_plane(const PreparedFrame& frame, const std::vector<Match>& matches,
                                    const Eigen::Isometry3d& T_w_c_guess) const;
  void refine_pose(const PreparedFrame& frame, PoseEstimate& estimate, TrackedFrame& record) const;
  Eigen::Isometry3d motion_model_pose(double stamp) const;
  void decide_and_insert_keyframe(const PreparedFrame& frame, const std::vector<Match>& inliers,
                                  TrackedFrame& record);
  void insert_keyframe(const PreparedFrame& frame, const Eigen::Isometry3d& T_w_c,
                       const std::vector<Match>& inliers);
  // The depth image resampled to pinhole geometry (unchanged for undistorted cameras).
  cv::Mat pinhole_depth(const cv::Mat& depth) const;

  Camera camera_;
  Settings settings_;
  Map map_;
  std::vector<StampedPose> poses_;             // every tracked frame, in order
  std::map<size_t, WindowCode> window_codes_;  // recent frames' codes, by frame index
  cv::Mat previous_depth_;                     // as recorded, for dense alignment
  bool previous_lost_ = false;
  bool velocity_known_ = false;  // the last two frames were tracked, not lost or re-acquired
  cv::Mat undistort_map_x_, undistort_map_y_;  // depth remap for distorted cameras
};

}  // namespace slamkit
