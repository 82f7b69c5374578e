#pragma once
// A keyframe (docs/method.md#keyframes): its timestamp, its pose and inverse, its ORB
// features, the map points its keypoints observe, and its place in the covisibility graph and
// spanning tree.
#include <Eigen/Geometry>
#include <map>
#include <opencv2/core.hpp>
#include <vector>

#include "keyframes/window_code.h"

namespace slamkit {

struct Keyframe {
  size_t frame_index = 0;  // index of the frame in the sequence
  double stamp = 0;
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_c_w = Eigen::Isometry3d::Identity();
  std::vector<cv::KeyPoint> keypoints;       // raw pixels, as extracted
  std::vector<Eigen::Vector2d> undistorted;  // ideal pinhole pixels
  std::vector<float> depths;                 // metres at each keypoint, 0 = none
  cv::Mat descriptors;                       // N x 32 CV_8U
  std::vector<int> point_ids;                // per keypoint: map point index, -1 = none
  WindowCode window_code;                    // for finding similar views when lost

  // Covisibility: shared points with every other keyframe that shares any, and the
  // neighbours linked in the graph (>= covisibility_min_shared points, or the best one),
  // by decreasing weight then increasing index.
  std::map<int, int> shared_points;
  std::vector<int> covisible;
  int parent = -1;  // spanning tree: the best neighbour at insertion (-1 for the first)
  std::vector<int> children;
  // Culled as redundant (Map::cull_keyframe): no observations, links or children any more; it
  // follows its parent at T_parent_c, its pose relative to the parent when it was culled.
  bool culled = false;
  Eigen::Isometry3d T_parent_c = Eigen::Isometry3d::Identity();

  void set_pose(const Eigen::Isometry3d& T_world_camera) {
    T_w_c = T_world_camera;
    T_c_w = T_world_camera.inverse();
  }
  Eigen::Vector3d centre() const { return T_w_c.translation(); }
};

}  // namespace slamkit
