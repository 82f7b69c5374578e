#pragma once
// Descriptors for the vocabulary tests: random ones, and noisy copies that stay near their
// original (as one scene point's descriptor does from frame to frame).
#include <opencv2/core.hpp>
#include <random>
#include <vector>

#include "features/descriptor.h"

namespace slamkit::test {

inline cv::Mat random_descriptors(int rows, std::mt19937& rng) {
  cv::Mat d(rows, kDescriptorBytes, CV_8U);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < kDescriptorBytes; ++c) d.at<uint8_t>(r, c) = uint8_t(rng() & 0xff);
  return d;
}

// `source` with `flips` random bits of each row inverted (a bit may be drawn twice).
inline cv::Mat flip_bits(const cv::Mat& source, int flips, std::mt19937& rng) {
  cv::Mat d = source.clone();
  for (int r = 0; r < d.rows; ++r)
    for (int f = 0; f < flips; ++f) {
      const int bit = int(rng() % (kDescriptorBytes * 8));
      d.at<uint8_t>(r, bit / 8) ^= uint8_t(1u << (bit % 8));
    }
  return d;
}

// Images drawn from a pool of `prototypes` scene descriptors: each image sees `per_image` of
// them (random picks) with up to 8 bits of noise. Clustered like real features.
inline std::vector<cv::Mat> clustered_images(int images, int per_image, int prototypes,
                                             unsigned seed) {
  std::mt19937 rng(seed);
  const cv::Mat pool = random_descriptors(prototypes, rng);
  std::vector<cv::Mat> out;
  for (int i = 0; i < images; ++i) {
    cv::Mat picked(per_image, kDescriptorBytes, CV_8U);
    for (int r = 0; r < per_image; ++r) pool.row(int(rng() % prototypes)).copyTo(picked.row(r));
    out.push_back(flip_bits(picked, 8, rng));
  }
  return out;
}

}  // namespace slamkit::test
