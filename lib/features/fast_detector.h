#pragma once
// FAST corner candidates (no non-maximum suppression: the caller suppresses by Shi-Tomasi).
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/orb_settings.h"

namespace slamkit {

// Every pixel of `region` (at least 3 px inside `image`) that passes the segment test at
// `threshold`, in `image` coordinates, in raster order.
std::vector<cv::Point> detect_fast(const cv::Mat& image, const cv::Rect& region, int threshold,
                                   FastType type);

// The FAST-12 segment test at one pixel: quick test on circle pixels 1, 5, 9, 13 (3 of 4 must
// pass), then 12 contiguous pixels all brighter than centre + t or all darker than centre - t.
bool passes_fast12(const cv::Mat& image, cv::Point p, int threshold);

}  // namespace slamkit
