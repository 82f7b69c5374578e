#include "features/equivalent_grey.h"

#include <stdexcept>

namespace slamkit {

cv::Mat equivalent_grey(const cv::Mat& image) {
  if (image.type() == CV_8UC1) return image.clone();  // a pyramid must not alias the caller's
  if (image.type() != CV_8UC3)
    throw std::invalid_argument("equivalent_grey: needs CV_8UC3 or CV_8UC1");
  // A loop of our own: cv::transform (the library's way) goes through floats and took 4 times
  // as long. (b + g + r) / 3 has a fraction of 0, 1/3 or 2/3, so + 1 then truncating rounds it
  // to the nearest integer, exactly.
  cv::Mat grey(image.size(), CV_8UC1);
  for (int v = 0; v < image.rows; ++v) {
    const uchar* bgr = image.ptr<uchar>(v);
    uchar* out = grey.ptr<uchar>(v);
    for (int u = 0; u < image.cols; ++u, bgr += 3) {
      out[u] = static_cast<uchar>((bgr[0] + bgr[1] + bgr[2] + 1) / 3);
    }
  }
  return grey;
}

}  // namespace slamkit
