#include "tracking/depth_pyramid.h"

#include <algorithm>

namespace slamkit {

cv::Mat downsample_depth(const cv::Mat& depth) {
  CV_Assert(depth.type() == CV_32F);
  cv::Mat half(depth.rows / 2, depth.cols / 2, CV_32F);
  for (int v = 0; v < half.rows; ++v) {
    const float* top = depth.ptr<float>(2 * v);
    const float* bottom = depth.ptr<float>(2 * v + 1);
    float* out = half.ptr<float>(v);
    for (int u = 0; u < half.cols; ++u) {
      float valid[4];
      int n = 0;
      for (float z : {top[2 * u], top[2 * u + 1], bottom[2 * u], bottom[2 * u + 1]})
        if (z > 0) valid[n++] = z;
      std::sort(valid, valid + n);
      out[u] = n > 0 ? valid[(n - 1) / 2] : 0.0f;
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
