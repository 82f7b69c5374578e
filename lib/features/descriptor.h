#pragma once
// Steered BRIEF descriptors (docs/method.md#features).
#include <opencv2/core.hpp>
#include <array>
#include <cstdint>
#include <vector>

namespace slamkit {

constexpr int kDescriptorBytes = 32;  // 256 bits
// One descriptor held by value (a map point's, a vocabulary node's).
using Descriptor = std::array<uint8_t, kDescriptorBytes>;

// Steered BRIEF, 256 bits, with ORB's learned pattern, on `level_image` smoothed by a 7x7
// Gaussian of sigma 2, rotated by each keypoint's angle. Keypoints are in level_image pixels;
// they must lie at least 19 px inside it. Returns keypoints.size() x 32 CV_8U, row i for
// keypoint i.
cv::Mat steered_brief(const cv::Mat& level_image, const std::vector<cv::KeyPoint>& keypoints);

// Hamming distance between two 32-byte descriptors (the CPU's popcount where it has one, else
// OpenCV's cv::hal::normHamming).
int descriptor_distance(const uchar* a, const uchar* b);

}  // namespace slamkit
