#include "io/png_samples.h"

#include <cstdint>
#include <opencv2/imgproc.hpp>

namespace slamkit {

cv::Mat stored_samples_to_opencv(const unsigned char* first_row, size_t stride,
                                 const PngHeader& header) {
  const int rows = int(header.height), cols = int(header.width), channels = header.channels();
  cv::Mat image;
  if (header.bit_depth == 8) {
    image = cv::Mat(rows, cols, CV_8UC(channels), const_cast<unsigned char*>(first_row), stride);
  } else {
    // OpenCV cannot view 16-bit samples at an odd stride: swap while copying, row by row.
    image.create(rows, cols, CV_16UC(channels));
    const size_t samples = size_t(cols) * size_t(channels);
    for (int r = 0; r < rows; ++r) {
      const unsigned char* in = first_row + size_t(r) * stride;
      auto* out = image.ptr<uint16_t>(r);
      for (size_t k = 0; k < samples; ++k) out[k] = uint16_t(in[2 * k] << 8 | in[2 * k + 1]);
    }
  }
  cv::Mat result;
  if (channels == 3)
    cv::cvtColor(image, result, cv::COLOR_RGB2BGR);
  else if (channels == 4)
    cv::cvtColor(image, result, cv::COLOR_RGBA2BGRA);
  else
    result = header.bit_depth == 8 ? image.clone() : image;
  return result;
}

}  // namespace slamkit
