#include "features/equivalent_grey.h"

#include <stdexcept>

namespace slamkit {

cv::Mat equivalent_grey(const cv::Mat& image) {
  if (image.type() == CV_8UC1) return image.clone();  // a pyramid must not alias the caller's
  if (image.type() != CV_8UC3)
    throw std::invalid_argument("equivalent_grey: needs CV_8UC3 or CV_8UC1");
  cv::Mat grey;
  cv::transform(image, grey, cv::Matx13f(1.f / 3, 1.f / 3, 1.f / 3));
  return grey;
}

}  // namespace slamkit
