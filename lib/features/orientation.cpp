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
  long m01 = 0, m10 = 0;
  for (int v = -radius; v <= radius; ++v) {
    const int w = half[std::abs(v)];
    const uchar* row = grey.ptr<uchar>(centre.y + v) + centre.x;
    long row_sum = 0;
    for (int u = -w; u <= w; ++u) {
      row_sum += row[u];
      m10 += static_cast<long>(u) * row[u];
    }
    m01 += static_cast<long>(v) * row_sum;
  }
  double degrees = std::atan2(static_cast<double>(m01), static_cast<double>(m10)) * 180.0 / M_PI;
  if (degrees < 0) degrees += 360.0;
  return static_cast<float>(degrees >= 360.0 ? 0.0 : degrees);
}

}  // namespace slamkit
