#include "io/png_source.h"

#include <lodepng.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"
#include "io/png_file.h"

namespace slamkit {
namespace {

// Deflate's largest possible ratio (258-byte matches coded in 2 bits): data that claims to
// inflate to more than this many times the file's size cannot be a valid PNG.
constexpr double kMaxDeflateRatio = 1032;

const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

}  // namespace

int PngHeader::channels() const {
  switch (colour_type) {
    case 2:
      return 3;
    case 4:
      return 2;
    case 6:
      return 4;
    default:
      return 1;
  }
}

double PngHeader::raw_bytes() const {
  const double row_bits = double(width) * channels() * bit_depth;
  return double(height) * (1 + std::ceil(row_bits / 8));
}

PngSource load_png_source(const std::filesystem::path& path) {
  PngSource png;
  png.name = path.string();
  std::ifstream file(path, std::ios::binary);
  if (!file) throw_input_error(png.name, "cannot open image");
  unsigned char signature[8] = {};
  if (!file.read(reinterpret_cast<char*>(signature), 8) ||
      !std::equal(signature, signature + 8, kSignature))
    throw_input_error(png.name, "not a PNG file");
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  if (size < 8) throw_input_error(png.name, "cannot read image");
  png.bytes.resize(size_t(size));
  file.seekg(0);
  if (!file.read(reinterpret_cast<char*>(png.bytes.data()), size))
    throw_input_error(png.name, "cannot read image");

  LodePNGState state;
  lodepng_state_init(&state);
  unsigned width = 0, height = 0;
  const unsigned error =
      lodepng_inspect(&width, &height, &state, png.bytes.data(), png.bytes.size());
  png.header = {width, height, int(state.info_png.color.bitdepth),
                int(state.info_png.color.colortype), state.info_png.interlace_method != 0};
  lodepng_state_cleanup(&state);
  if (error)
    throw_input_error(png.name, std::string("cannot decode image: ") + lodepng_error_text(error));
  if (width > unsigned(kMaxImageSide) || height > unsigned(kMaxImageSide) ||
      png.header.raw_bytes() > double(kMaxImageBytes))
    throw_input_error(png.name, "the header claims a " + std::to_string(width) + " x " +
                                    std::to_string(height) + " image (" +
                                    std::to_string(uint64_t(png.header.raw_bytes()) >> 20) +
                                    " MiB decoded); images are limited to " +
                                    std::to_string(kMaxImageSide) + " pixels a side and " +
                                    std::to_string(kMaxImageBytes >> 20) + " MiB");
  if (png.header.raw_bytes() > kMaxDeflateRatio * double(png.bytes.size()))
    throw_input_error(png.name, "cannot decode image: the header declares " +
                                    std::to_string(width) + " x " + std::to_string(height) +
                                    " pixels, more than its " + std::to_string(png.bytes.size()) +
                                    " bytes can hold");
  return png;
}

}  // namespace slamkit
