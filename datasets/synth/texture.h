#pragma once
// A surface's colour image with a mip-map pyramid, sampled trilinearly so that distant or
// slanted surfaces are prefiltered instead of aliasing into sparkle.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

namespace slamkit::synth {

class Texture {
 public:
  // `image` is CV_8UC3 (BGR) covering the surface at `texels_per_metre`.
  Texture(const cv::Mat& image, double texels_per_metre);

  // BGR colour (0..255) at (u, v) metres from the image's top-left corner, averaged over a
  // footprint of `footprint_m` metres (the size of one camera pixel on the surface).
  Eigen::Vector3f sample(double u, double v, double footprint_m) const;

 private:
  Eigen::Vector3f bilinear(int level, double u, double v) const;

  std::vector<cv::Mat> levels_;  // levels_[k] has 2^-k times the resolution of level 0
  double texels_per_metre_;
};

}  // namespace slamkit::synth
