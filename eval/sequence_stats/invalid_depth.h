#pragma once
// How much of a depth image is invalid (0), overall and near depth discontinuities, where
// structured-light and stereo sensors lose most pixels (shadows, mixed pixels).
#include <cstddef>
#include <opencv2/core.hpp>

namespace slamkit::stats {

struct InvalidDepthSettings {
  int edge_radius = 3;     // pixels: the edge region is every pixel this close to a discontinuity
  double edge_jump = 0.1;  // a discontinuity: valid depths in the window differ by more than
                           // this share of the nearest one
};

struct InvalidCounts {
  size_t pixels = 0;
  size_t invalid = 0;
  size_t edge_pixels = 0;   // pixels in the edge region
  size_t edge_invalid = 0;  // invalid ones among them

  InvalidCounts& operator+=(const InvalidCounts& other);
  double share() const { return pixels ? double(invalid) / double(pixels) : 0.0; }
  double edge_region_share() const { return pixels ? double(edge_pixels) / double(pixels) : 0.0; }
  double edge_share() const {
    return edge_pixels ? double(edge_invalid) / double(edge_pixels) : 0.0;
  }
  double off_edge_share() const {
    const size_t rest = pixels - edge_pixels;
    return rest ? double(invalid - edge_invalid) / double(rest) : 0.0;
  }
};

// Counts for one depth image (CV_32F metres, 0 invalid). A pixel is in the edge region when the
// valid depths of the (2r+1)^2 window around it span more than edge_jump of their minimum, so
// an invalid band narrower than the window between two surfaces counts as edge too.
InvalidCounts count_invalid(const cv::Mat& depth, const InvalidDepthSettings& settings);

}  // namespace slamkit::stats
