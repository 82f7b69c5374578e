#include "features/frame_features.h"

#include <cmath>

namespace slamkit {

float depth_at(const cv::Mat& depth, const cv::KeyPoint& keypoint) {
  const int u = cvRound(keypoint.pt.x), v = cvRound(keypoint.pt.y);
  if (u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) return 0.0f;
  const float z = depth.at<float>(v, u);
  return std::isfinite(z) && z > 0 ? z : 0.0f;
}

std::vector<float> keypoint_depths(const FrameFeatures& features, const cv::Mat& depth) {
  std::vector<float> depths(features.size());
  for (size_t i = 0; i < features.size(); ++i) depths[i] = depth_at(depth, features.keypoints[i]);
  return depths;
}

}  // namespace slamkit
