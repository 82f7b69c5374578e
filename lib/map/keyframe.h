#pragma once
// A keyframe (SPEC section 3): its timestamp, its pose and inverse, its ORB features and the
// map points its keypoints observe.
#include <Eigen/Geometry>
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
};

}  // namespace slamkit
