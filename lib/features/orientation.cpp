#include "features/orientation.h"

#include <cmath>
#include <cstdlib>
#include <vector>

namespace slamkit {

std::vector<int> disc_half_widths(int radius) {
  // ORB's construction (Rublee et al., as cv::ORB and ORB-SLAM2): rows below 45 degrees by
  // rounding, the rows above mirrored from the columns, so the disc is symmetric under x <-> y,
  // which rotation invariance needs.
  std::vector<int> half(radius + 1);
  const int v_max = static_cast<int>(std::floor(radius * std::sqrt(2.0) / 2 + 1));
  const int v_min = static_cast<int>(std::ceil(radius * std::sqrt(2.0) / 2));
  for (int v = 0; v <= std::min(v_max, radius); ++v) {
    half[v] =
        static_cast<int>(std::lround(std::sqrt(static_cast<double>(radius * radius - v * v))));
  }
  for (int v = radius, v0 = 0; v >= v_min; --v) {
    while (half[v0] == half[v0 + 1]) ++v0;
    half[v] = v0++;
  }
  return half;
}

float intensity_centroid_angle(const cv::Mat& grey, cv::Point centre, int radius) {
  thread_local std::vector<int> half;  // the disc for the last radius asked, per thread
  if (static_cast<int>(half.size()) != radius + 1) half = disc_half_widths(radius);
  // Rows v and -v together: m10 takes their sum, m01 their difference (half the passes).
  int m01 = 0, m10 = 0;  // |m| <= 255 r (2r + 1)^2: 32 bits hold it up to r = 100
  const uchar* middle = grey.ptr<uchar>(centre.y) + centre.x;
  for (int u = -radius; u <= radius; ++u) m10 += u * middle[u];
  const size_t step = grey.step1();
  for (int v = 1; v <= radius; ++v) {
    const int w = half[v];
    const uchar* below = middle + v * step;
    const uchar* above = middle - v * step;
    int sum_x = 0, difference = 0;
    for (int u = -w; u <= w; ++u) {
      sum_x += u * (below[u] + above[u]);
      difference += below[u] - above[u];
    }
    m10 += sum_x;
    m01 += v * difference;
  }
  double degrees = std::atan2(static_cast<double>(m01), static_cast<double>(m10)) * 180.0 / M_PI;
  if (degrees < 0) degrees += 360.0;
  return static_cast<float>(degrees >= 360.0 ? 0.0 : degrees);
}

}  // namespace slamkit
