#include "tracking/depth_pyramid.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace slamkit {
namespace {

// The comparators that sort four values (a sorting network).
constexpr std::pair<int, int> kSortFour[] = {{0, 1}, {2, 3}, {0, 2}, {1, 3}, {1, 2}};

}  // namespace

cv::Mat downsample_depth(const cv::Mat& depth) {
  CV_Assert(depth.type() == CV_32F);
  cv::Mat half(depth.rows / 2, depth.cols / 2, CV_32F);
  for (int v = 0; v < half.rows; ++v) {
    const float* top = depth.ptr<float>(2 * v);
    const float* bottom = depth.ptr<float>(2 * v + 1);
    float* out = half.ptr<float>(v);
    for (int u = 0; u < half.cols; ++u) {
      // Sorted with the holes as +inf, the lower median of the n valid ones is s[(n - 1) / 2].
      float s[4];
      int n = 0;
      const float block[4] = {top[2 * u], top[2 * u + 1], bottom[2 * u], bottom[2 * u + 1]};
      for (int k = 0; k < 4; ++k) {
        n += block[k] > 0;
        s[k] = block[k] > 0 ? block[k] : std::numeric_limits<float>::infinity();
      }
      for (const auto& [a, b] : kSortFour) {  // min and max: no branch to mispredict
        const float low = std::min(s[a], s[b]);
        s[b] = std::max(s[a], s[b]);
        s[a] = low;
      }
      out[u] = n > 0 ? s[(n - 1) / 2] : 0.0f;
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
