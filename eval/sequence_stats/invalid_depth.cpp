#include "eval/sequence_stats/invalid_depth.h"

#include <limits>
#include <opencv2/imgproc.hpp>

namespace slamkit::stats {

InvalidCounts& InvalidCounts::operator+=(const InvalidCounts& other) {
  pixels += other.pixels;
  invalid += other.invalid;
  edge_pixels += other.edge_pixels;
  edge_invalid += other.edge_invalid;
  return *this;
}

InvalidCounts count_invalid(const cv::Mat& depth, const InvalidDepthSettings& settings) {
  CV_Assert(depth.type() == CV_32FC1);
  const cv::Mat invalid = depth <= 0;
  // Window maximum and minimum over valid pixels only: invalid ones are 0 for the maximum
  // already and made +inf for the minimum; image borders are ignored by both by default.
  const int side = 2 * settings.edge_radius + 1;
  const cv::Mat window = cv::getStructuringElement(cv::MORPH_RECT, {side, side});
  cv::Mat highest, lowest, for_minimum = depth.clone();
  for_minimum.setTo(std::numeric_limits<float>::infinity(), invalid);
  cv::dilate(depth, highest, window);
  cv::erode(for_minimum, lowest, window);
  // A window without valid pixels compares -inf > inf: not edge.
  const cv::Mat edge = (highest - lowest) > settings.edge_jump * lowest;

  InvalidCounts counts;
  counts.pixels = depth.total();
  counts.invalid = size_t(cv::countNonZero(invalid));
  counts.edge_pixels = size_t(cv::countNonZero(edge));
  counts.edge_invalid = size_t(cv::countNonZero(edge & invalid));
  return counts;
}

}  // namespace slamkit::stats
