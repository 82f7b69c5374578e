#include "datasets/synth/texture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace slamkit::synth {

Texture::Texture(const cv::Mat& image, double texels_per_metre)
    : texels_per_metre_(texels_per_metre) {
  CV_Assert(image.type() == CV_8UC3 && image.cols >= 2 && image.rows >= 2);
  levels_.push_back(image);
  // pyrDown's Gaussian is the prefilter; stop when a level would lose a whole dimension.
  while (levels_.back().cols >= 4 && levels_.back().rows >= 4) {
    cv::Mat next;
    cv::pyrDown(levels_.back(), next);
    levels_.push_back(next);
  }
}

Eigen::Vector3f Texture::bilinear(int level, double u, double v) const {
  const cv::Mat& img = levels_[level];
  const double scale = texels_per_metre_ / double(1 << level);
  // Texel centres sit at half-integer positions; addressing clamps to the edge.
  const double x = std::clamp(u * scale - 0.5, 0.0, double(img.cols - 1));
  const double y = std::clamp(v * scale - 0.5, 0.0, double(img.rows - 1));
  const int x0 = std::min(int(x), img.cols - 2), y0 = std::min(int(y), img.rows - 2);
  const int x1 = x0 + 1, y1 = y0 + 1;
  const float fx = float(x - x0), fy = float(y - y0);
  const auto* r0 = img.ptr<cv::Vec3b>(y0);
  const auto* r1 = img.ptr<cv::Vec3b>(y1);
  Eigen::Vector3f out;
  for (int c = 0; c < 3; ++c) {
    const float top = r0[x0][c] + fx * (r0[x1][c] - r0[x0][c]);
    const float bottom = r1[x0][c] + fx * (r1[x1][c] - r1[x0][c]);
    out[c] = top + fy * (bottom - top);
  }
  return out;
}

Eigen::Vector3f Texture::sample(double u, double v, double footprint_m) const {
  // Level of detail log2(texels per pixel), linearly interpolated between powers of two
  // (frexp instead of log2: cheaper, and as good for choosing and blending levels).
  int exponent = 0;
  const double mantissa = std::frexp(std::max(footprint_m * texels_per_metre_, 1.0), &exponent);
  const double lod = std::min(exponent - 2 + 2 * mantissa, double(levels_.size() - 1));
  const int lo = int(lod);
  const float blend = float(lod - lo);
  if (blend == 0.0f || lo + 1 >= int(levels_.size())) return bilinear(lo, u, v);
  return (1.0f - blend) * bilinear(lo, u, v) + blend * bilinear(lo + 1, u, v);
}

}  // namespace slamkit::synth
