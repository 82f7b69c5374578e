#pragma once
// ORB-SLAM2's last loop check (ComputeSim3's SearchByProjection, docs/method.md#loop-closing):
// with the measured loop pose, the map points around the candidate (its own and those of all
// its covisible neighbours) are projected into the keyframe and matched to keypoints nearby. A
// true loop sees its whole neighbourhood line up; a pose fitted to a few pairs that fit a wrong
// pose as well (a far wall, one surface) does not.
#include <Eigen/Geometry>
#include <vector>

#include "core/camera.h"
#include "map/map.h"

namespace slamkit {

struct LoopPointMatch {
  int keypoint;  // of the keyframe
  int point;     // map point around the candidate
};

// The keyframe's keypoints not yet `taken` matched to the candidate neighbourhood's points
// projected with the keyframe at T_w_keyframe (the world of the candidate's side): within
// radius x the predicted level's scale (pixels), the level or the one below, the closest
// descriptor if at most max_distance bits; one point per keypoint, the closest descriptor
// (then the lower point index). Sorted by keypoint.
std::vector<LoopPointMatch> match_loop_neighbourhood(const Map& map, int keyframe, int candidate,
                                                     const Eigen::Isometry3d& T_w_keyframe,
                                                     const std::vector<bool>& taken,
                                                     const Camera& camera, double radius,
                                                     int max_distance);

}  // namespace slamkit
