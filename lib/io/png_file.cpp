#include "io/png_file.h"

#include <memory>
#include <string>

#include "core/error.h"
#include "io/png_chunks.h"
#include "io/png_isal_inflate.h"
#include "io/png_libpng.h"
#include "io/png_samples.h"
#include "io/png_source.h"
#include "io/png_unfilter.h"

namespace slamkit {
namespace {

// The layouts decoded here rather than by libpng: 8- or 16-bit grey, RGB or RGBA, not
// interlaced (TUM's and ours).
bool common_layout(const PngHeader& header) {
  const bool colour_type =
      header.colour_type == 0 || header.colour_type == 2 || header.colour_type == 6;
  return colour_type && (header.bit_depth == 8 || header.bit_depth == 16) && !header.interlaced;
}

cv::Mat decode_common_layout(const PngSource& png) {
  const std::vector<unsigned char> image_data = checked_image_data(png);
  const PngHeader& header = png.header;
  const size_t pixel_bytes = size_t(header.channels() * header.bit_depth / 8);
  const size_t row_bytes = size_t(header.width) * pixel_bytes;
  const size_t scanlines_size = size_t(header.height) * (row_bytes + 1);
  // Not a std::vector: its zero fill would be one more pass over the image.
  const std::unique_ptr<unsigned char[]> scanlines(new unsigned char[scanlines_size]);
  std::string error;
  if (!inflate_with_isal(image_data.data(), image_data.size(), scanlines.get(), scanlines_size,
                         error))
    throw_input_error(png.name, "cannot decode image: " + error);
  const size_t undone = unfilter_scanlines(scanlines.get(), header.height, row_bytes, pixel_bytes);
  if (undone < header.height)
    throw_input_error(png.name, "cannot decode image: unknown filter type " +
                                    std::to_string(scanlines[undone * (row_bytes + 1)]) +
                                    " in row " + std::to_string(undone));
  return stored_samples_to_opencv(scanlines.get() + 1, row_bytes + 1, header);
}

}  // namespace

cv::Mat read_png(const std::filesystem::path& path) {
  const PngSource png = load_png_source(path);
  return common_layout(png.header) ? decode_common_layout(png) : decode_png_with_libpng(png);
}

cv::Mat read_png_with_libpng(const std::filesystem::path& path) {
  return decode_png_with_libpng(load_png_source(path));
}

}  // namespace slamkit
