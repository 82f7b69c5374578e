#pragma once
// Shrinking a grey image by area averaging: the pyramid's INTER_AREA (docs/method.md#features).
#include <opencv2/core.hpp>

namespace slamkit {

// `grey` (CV_8UC1) shrunk to `size` (at most its own in each axis, at least 1 px): each output
// pixel is the mean of the source area it covers, partial pixels weighted by their overlap,
// rounded to the nearest grey level. This is cv::resize's INTER_AREA; the two differ by at most
// one grey level (fixed-point weights here, floats there).
cv::Mat area_downscale(const cv::Mat& grey, cv::Size size);

}  // namespace slamkit
