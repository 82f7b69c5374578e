#pragma once
// A PNG's samples as stored (RGB order, 16-bit samples big-endian) into OpenCV's layout.
#include <opencv2/core.hpp>

#include "io/png_source.h"

namespace slamkit {

// `header.height` rows of `stride` bytes from `first_row`, 8- or 16-bit grey, RGB or RGBA:
// the image as read_png (io/png_file.h) returns it, in memory of its own: grey as is, colour
// as BGR or BGRA, 16-bit samples in the machine's order.
cv::Mat stored_samples_to_opencv(const unsigned char* first_row, size_t stride,
                                 const PngHeader& header);

}  // namespace slamkit
