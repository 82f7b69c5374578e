#pragma once
// A landmark: a 3D point seen in keyframes, with the descriptor that matches it.
#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace slamkit {

struct MapPoint {
  Eigen::Vector3d p_w = Eigen::Vector3d::Zero();  // world position, metres
  cv::Mat descriptor;        // 1 x 32 CV_8U, from the keyframe that created the point
  int octave = 0;            // pyramid level it was detected on
  size_t first_keyframe = 0; // index into Map::keyframes()
  int observations = 1;      // keyframes that saw it
};

}  // namespace slamkit
