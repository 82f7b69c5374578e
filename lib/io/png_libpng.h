#pragma once
// libpng's decoder, for read_png_with_libpng and for the layouts the fast decoder leaves.
#include <opencv2/core.hpp>

#include "io/png_source.h"

namespace slamkit {

// As read_png documents; throws InputError naming the file.
cv::Mat decode_png_with_libpng(const PngSource& png);

}  // namespace slamkit
