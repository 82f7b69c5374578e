#include "io/png_file.h"

#include "io/png_isal_inflate.h"
#include "io/png_libpng.h"
#include "io/png_lodepng.h"
#include "io/png_source.h"

namespace slamkit {

cv::Mat read_png(const std::filesystem::path& path) {
  const PngSource png = load_png_source(path);
  return lodepng_decodes(png.header) ? decode_png_with_lodepng(png, inflate_with_isal)
                                     : decode_png_with_libpng(png);
}

cv::Mat read_png_with_libpng(const std::filesystem::path& path) {
  return decode_png_with_libpng(load_png_source(path));
}

}  // namespace slamkit
