#include "png_lodepng.h"

#include <cstdlib>
#include <memory>

#include "core/error.h"
#include "io/png_chunks.h"
#include "io/png_isal_inflate.h"
#include "io/png_samples.h"

namespace slamkit::bench {
namespace {

struct StateCleanup {
  void operator()(LodePNGState* state) const { lodepng_state_cleanup(state); }
};
struct PixelsFree {
  void operator()(unsigned char* pixels) const { std::free(pixels); }
};

}  // namespace

unsigned inflate_hook_with_isal(unsigned char** out, size_t* out_size, const unsigned char* in,
                                size_t in_size, const LodePNGDecompressSettings* settings) {
  auto& context = *static_cast<InflateContext*>(const_cast<void*>(settings->custom_context));
  *out = static_cast<unsigned char*>(std::malloc(context.expected_bytes));
  if (!*out) return 1;
  *out_size = context.expected_bytes;
  return inflate_with_isal(in, in_size, *out, context.expected_bytes, context.error) ? 0 : 1;
}

cv::Mat decode_png_with_lodepng(const PngSource& png, ZlibInflate inflate) {
  checked_image_data(png);  // the CRCs, as read_png checks them
  InflateContext context;
  context.expected_bytes = size_t(png.header.raw_bytes());
  LodePNGState state;
  lodepng_state_init(&state);
  const std::unique_ptr<LodePNGState, StateCleanup> cleanup(&state);
  state.decoder.ignore_crc = 1;     // checked above, faster than lodepng's byte-wise check
  state.decoder.color_convert = 0;  // the samples as stored
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
  const size_t row_bytes = size_t(width) * size_t(png.header.channels() * png.header.bit_depth / 8);
  return stored_samples_to_opencv(pixels.get(), row_bytes, png.header);
}

}  // namespace slamkit::bench
