#include "io/png_lodepng.h"

#include <zlib.h>

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace slamkit {
namespace {

uint32_t big_endian_32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

// Every chunk whole, with the right CRC, or InputError naming the chunk. lodepng is told to
// skip its own CRC check, which goes a byte at a time (a quarter of a colour frame's decode;
// zlib's crc32 is several times faster), and its message for a cut chunk is misleading. A
// bad CRC is an error in any chunk (libpng only warns for ancillary ones; TUM's frames and
// ours have none).
void check_chunks(const PngSource& png) {
  const unsigned char* end = png.bytes.data() + png.bytes.size();
  for (const unsigned char* chunk = png.bytes.data() + 8; end - chunk >= 12;
       chunk = lodepng_chunk_next_const(chunk, end)) {
    const std::string type(reinterpret_cast<const char*>(chunk + 4), 4);
    const size_t length = lodepng_chunk_length(chunk);
    if (length > size_t(end - chunk) - 12)
      throw_input_error(png.name,
                        "cannot decode image: the file ends inside its " + type + " chunk");
    if (crc32_z(0, chunk + 4, length + 4) != big_endian_32(chunk + 8 + length))
      throw_input_error(png.name, "cannot decode image: CRC error in the " + type + " chunk");
    if (type == "IEND") return;
  }
}

// lodepng's decoded samples (RGB order, 16-bit big-endian, as stored) in OpenCV's layout;
// 16-bit samples are swapped in lodepng's buffer, which is ours.
cv::Mat to_opencv_layout(unsigned char* pixels, const PngHeader& header) {
  const int depth = header.bit_depth == 16 ? CV_16U : CV_8U;
  const cv::Mat stored(int(header.height), int(header.width), CV_MAKETYPE(depth, header.channels()),
                       pixels);
  if (depth == CV_16U) {
    auto* samples = reinterpret_cast<uint16_t*>(pixels);
    const size_t count = stored.total() * size_t(stored.channels());
    for (size_t k = 0; k < count; ++k) samples[k] = uint16_t(samples[k] << 8 | samples[k] >> 8);
  }
  cv::Mat image;
  if (header.channels() == 3)
    cv::cvtColor(stored, image, cv::COLOR_RGB2BGR);
  else if (header.channels() == 4)
    cv::cvtColor(stored, image, cv::COLOR_RGBA2BGRA);
  else
    image = stored.clone();
  return image;
}

struct StateCleanup {
  void operator()(LodePNGState* state) const { lodepng_state_cleanup(state); }
};
struct PixelsFree {
  void operator()(unsigned char* pixels) const { std::free(pixels); }
};

}  // namespace

bool lodepng_decodes(const PngHeader& header) {
  const bool layout = header.colour_type == 0 || header.colour_type == 2 || header.colour_type == 6;
  return layout && (header.bit_depth == 8 || header.bit_depth == 16) && !header.interlaced;
}

cv::Mat decode_png_with_lodepng(const PngSource& png, ZlibInflate inflate) {
  check_chunks(png);
  InflateContext context;
  context.expected_bytes = size_t(png.header.raw_bytes());
  LodePNGState state;
  lodepng_state_init(&state);
  const std::unique_ptr<LodePNGState, StateCleanup> cleanup(&state);
  state.decoder.ignore_crc = 1;     // checked above
  state.decoder.color_convert = 0;  // the samples as stored; to_opencv_layout reorders them
  state.decoder.read_text_chunks = 0;
  state.decoder.zlibsettings.custom_zlib = inflate;
  state.decoder.zlibsettings.custom_context = &context;
  state.decoder.zlibsettings.max_output_size = context.expected_bytes;  // for lodepng's own
  unsigned char* decoded = nullptr;
  unsigned width = 0, height = 0;
  const unsigned error =
      lodepng_decode(&decoded, &width, &height, &state, png.bytes.data(), png.bytes.size());
  const std::unique_ptr<unsigned char, PixelsFree> pixels(decoded);
  if (error)
    throw_input_error(png.name, "cannot decode image: " +
                                    (context.error.empty() ? std::string(lodepng_error_text(error))
                                                           : context.error));
  return to_opencv_layout(pixels.get(), png.header);
}

}  // namespace slamkit
