#pragma once
// The paper's equivalent grey I_e = (R + G + B) / 3 (docs/method.md#keyframes). Features and
// the window code both read it, so one pyramid per frame serves both.
#include <opencv2/core.hpp>

namespace slamkit {

// CV_8UC1 from BGR (CV_8UC3), rounded to the nearest integer; a grey image is copied as is.
// Throws std::invalid_argument for other types.
cv::Mat equivalent_grey(const cv::Mat& image);

}  // namespace slamkit
