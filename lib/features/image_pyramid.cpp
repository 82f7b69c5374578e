#include "features/image_pyramid.h"

#include <cmath>
#include <stdexcept>

#include "features/area_downscale.h"

namespace slamkit {

ImagePyramid build_pyramid(const cv::Mat& grey, int num_levels, double scale_factor) {
  if (grey.type() != CV_8UC1) throw std::invalid_argument("build_pyramid: needs CV_8UC1");
  if (num_levels < 1 || scale_factor < 1) {
    throw std::invalid_argument("build_pyramid: needs levels >= 1 and scale factor >= 1");
  }
  ImagePyramid pyramid;
  pyramid.levels.resize(num_levels);
  pyramid.scales.resize(num_levels);
  pyramid.levels[0] = grey;
  pyramid.scales[0] = 1.0;
  for (int l = 1; l < num_levels; ++l) {
    const double scale = std::pow(scale_factor, l);
    const cv::Size size(cvRound(grey.cols / scale), cvRound(grey.rows / scale));
    // From level 0 each time (not from level l-1): the area average then covers the true footprint.
    pyramid.levels[l] = area_downscale(grey, size);
    pyramid.scales[l] = scale;
  }
  return pyramid;
}

cv::Point2f ImagePyramid::to_level0(const cv::Point2f& p, int level) const {
  const cv::Size s0 = levels[0].size(), sl = levels[level].size();
  const float rx = static_cast<float>(s0.width) / sl.width;
  const float ry = static_cast<float>(s0.height) / sl.height;
  return {(p.x + 0.5f) * rx - 0.5f, (p.y + 0.5f) * ry - 0.5f};
}

cv::Point2f ImagePyramid::from_level0(const cv::Point2f& p, int level) const {
  const cv::Size s0 = levels[0].size(), sl = levels[level].size();
  const float rx = static_cast<float>(sl.width) / s0.width;
  const float ry = static_cast<float>(sl.height) / s0.height;
  return {(p.x + 0.5f) * rx - 0.5f, (p.y + 0.5f) * ry - 0.5f};
}

}  // namespace slamkit
