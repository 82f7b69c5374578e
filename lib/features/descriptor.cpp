#include "features/descriptor.h"

#include <opencv2/core/hal/hal.hpp>
#include <opencv2/features2d.hpp>
#include <stdexcept>

namespace slamkit {

cv::Mat steered_brief(const cv::Mat& level_image, const std::vector<cv::KeyPoint>& keypoints) {
  if (keypoints.empty()) return cv::Mat(0, kDescriptorBytes, CV_8U);
  // ORB's pattern is not public API, so cv::ORB computes the bits. Given keypoints, cv::ORB
  // builds a pyramid of its own (INTER_LINEAR_EXACT) up to the highest octave; with octave 0
  // and one level it works on exactly this image: it pads it (BORDER_REFLECT_101), smooths it
  // (7x7, sigma 2) and reads the pattern rotated by keypoint.angle. It keeps the angles given.
  // edgeThreshold 0 turns off its border filter, so no keypoint is dropped and rows stay 1:1.
  std::vector<cv::KeyPoint> at_level = keypoints;
  for (cv::KeyPoint& k : at_level) k.octave = 0;
  const cv::Ptr<cv::ORB> orb = cv::ORB::create(static_cast<int>(keypoints.size()), 1.2f, 1, 0);
  cv::Mat descriptors;
  orb->compute(level_image, at_level, descriptors);
  if (descriptors.rows != static_cast<int>(keypoints.size()) ||
      at_level.size() != keypoints.size()) {
    throw std::logic_error("steered_brief: cv::ORB dropped keypoints");
  }
  return descriptors;
}

int descriptor_distance(const uchar* a, const uchar* b) {
  return cv::hal::normHamming(a, b, kDescriptorBytes);
}

}  // namespace slamkit
