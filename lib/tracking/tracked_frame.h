#pragma once
// What tracking did with one frame: its pose and the numbers behind it (tracking.csv).
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace slamkit {

enum class PoseSolver {
  kFirstFrame,    // the first frame defines the world frame
  kSvdRansac,     // >= 50 3D-3D pairs: closed form in RANSAC (paper)
  kPointToPlane,  // fewer: dense point-to-plane alignment (paper)
  kMotionModel,   // tracking failed: the velocity model gives the pose (paper)
};
const char* solver_name(PoseSolver solver);

// A keypoint of a frame matched to a map point, as the frame's final pose used it: undistorted
// pixels (moved to the colour stamp under a rolling shutter), so that the pose can be solved again
// once the back end has moved the points (tracking/frame_refinement.h).
struct MatchedKeypoint {
  int point_id = -1;
  float u = 0, v = 0;
  float depth = 0;  // metres; 0 = none
  float sigma = 1;  // pixels: the keypoint's level scale
};

struct TrackedFrame {
  size_t index = 0;
  double stamp = 0;
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  PoseSolver solver = PoseSolver::kFirstFrame;
  int features = 0;      // keypoints extracted
  int matches = 0;       // keypoints matched to map points
  int pairs_3d = 0;      // matches with valid depth (3D-3D pairs)
  int inliers = 0;       // matches kept by the pose solvers
  bool refined = false;  // motion-only bundle adjustment succeeded
  bool lost = false;     // the solvers failed; the pose is the motion model's
  std::string failure;   // why, when lost
  bool keyframe = false;
  // The keyframe sharing most points with the frame (itself, for a keyframe) and the frame's
  // pose relative to it when tracked: the back end's corrections of the keyframe carry over
  // to the frame (re-anchoring), as ORB-SLAM2 writes its trajectory.
  int reference_keyframe = -1;
  Eigen::Isometry3d T_ref_c = Eigen::Isometry3d::Identity();
  // The inlier matches of a frame that is not a keyframe and whose pose motion-only BA refined,
  // kept for frame refinement (optimization.refine_frames) and released by it.
  std::vector<MatchedKeypoint> matched;
  double similarity = 1;  // zeta against the latest keyframe and its neighbours
  // Per-step wall time, milliseconds.
  double match_ms = 0, pose_ms = 0, refine_ms = 0, keyframe_ms = 0;
};

}  // namespace slamkit
