#pragma once
// Procedural surface images: multi-scale value noise plus sharp-edged blobs, polygons,
// stripes, checker patches, lines and letters, so that ORB/FAST find corners on every
// textured surface. Plain styles give a uniform colour (the low-texture surfaces).
#include <cstdint>
#include <opencv2/core.hpp>

namespace slamkit::synth {

struct TextureStyle {
  cv::Scalar base{180, 180, 180};  // BGR mean colour
  cv::Scalar accent{90, 90, 90};   // BGR second colour the patterns draw with
  bool plain = false;              // uniform colour, no pattern at all
  double tile_size_m = 0;          // > 0: tiles with joints (floors), each its own shade

  static TextureStyle plain_colour(const cv::Scalar& bgr) { return {bgr, bgr, true, 0}; }
};

// A CV_8UC3 image covering width_m x height_m at `texels_per_metre`; the same arguments give
// the same image.
cv::Mat make_procedural_image(double width_m, double height_m, double texels_per_metre,
                              const TextureStyle& style, uint64_t seed);

}  // namespace slamkit::synth
