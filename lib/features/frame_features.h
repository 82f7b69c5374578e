#pragma once
// The ORB features of one frame, and the depth at each keypoint.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "features/image_pyramid.h"

namespace slamkit {

struct FrameFeatures {
  // pt in raw (distorted) level-0 pixels, octave = pyramid level, angle in degrees,
  // response = Shi-Tomasi, size = 31 * level scale (the patch, as cv::ORB).
  std::vector<cv::KeyPoint> keypoints;
  // keypoints[i].pt through the lens model: ideal pinhole pixels, for all geometry.
  std::vector<Eigen::Vector2d> undistorted;
  cv::Mat descriptors;  // CV_8U, keypoints.size() x 32, row i for keypoint i
  ImagePyramid pyramid;

  size_t size() const { return keypoints.size(); }
};

// Depth in metres at the keypoint's raw position (nearest pixel of the registered CV_32F depth
// image), 0 when outside the image or invalid (the depth image holds 0 there).
float depth_at(const cv::Mat& depth, const cv::KeyPoint& keypoint);

// depth_at() for every keypoint of a frame.
std::vector<float> keypoint_depths(const FrameFeatures& features, const cv::Mat& depth);

}  // namespace slamkit
