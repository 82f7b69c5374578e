#include "tracking/depth_pyramid.h"

#include <algorithm>
#include <limits>

namespace slamkit {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// A hole is +inf, so that it sorts after every measurement.
float or_inf(float z) { return z > 0 ? z : kInf; }

}  // namespace

cv::Mat downsample_depth(const cv::Mat& depth) {
  CV_Assert(depth.type() == CV_32F);
  cv::Mat half(depth.rows / 2, depth.cols / 2, CV_32F);
  for (int v = 0; v < half.rows; ++v) {
    const float* top = depth.ptr<float>(2 * v);
    const float* bottom = depth.ptr<float>(2 * v + 1);
    float* out = half.ptr<float>(v);
    // A sorting network (min and max, no branch), as a plain loop GCC vectorises.
#pragma omp simd
    for (int u = 0; u < half.cols; ++u) {
      const float a = or_inf(top[2 * u]), b = or_inf(top[2 * u + 1]);
      const float c = or_inf(bottom[2 * u]), d = or_inf(bottom[2 * u + 1]);
      const float ab_low = std::min(a, b), ab_high = std::max(a, b);
      const float cd_low = std::min(c, d), cd_high = std::max(c, d);
      const float s0 = std::min(ab_low, cd_low), middle_a = std::max(ab_low, cd_low);
      const float middle_b = std::min(ab_high, cd_high);  // the largest is not needed
      const float s1 = std::min(middle_a, middle_b), s2 = std::max(middle_a, middle_b);
      // The lower median of the n valid ones, s[(n - 1) / 2]: s1 when n >= 3 (s2 is a
      // measurement), s0 when n is 1 or 2, and 0 when there is none.
      out[u] = s2 < kInf ? s1 : s0 < kInf ? s0 : 0.0f;
    }
  }
  return half;
}

std::vector<cv::Mat> depth_pyramid(const cv::Mat& depth, int levels) {
  std::vector<cv::Mat> pyramid{depth};
  for (int l = 1; l < levels; ++l) pyramid.push_back(downsample_depth(pyramid.back()));
  return pyramid;
}

Camera camera_at_level(const Camera& camera, int level) {
  Camera c = camera;
  for (int l = 0; l < level; ++l) {
    c.fx /= 2, c.fy /= 2;
    c.cx = (c.cx + 0.5) / 2 - 0.5, c.cy = (c.cy + 0.5) / 2 - 0.5;
    c.width /= 2, c.height /= 2;
  }
  return c;
}

}  // namespace slamkit
