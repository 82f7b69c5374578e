#pragma once
// PNG decoding through lodepng with a pluggable inflate (lodepng's custom_zlib hook): lodepng
// parses the chunks and undoes the filters. read_png used this with ISA-L's inflate until it
// undid the filters itself; the benchmark keeps it beside read_png.
#include <lodepng.h>

#include <opencv2/core.hpp>
#include <string>

#include "io/png_source.h"

namespace slamkit::bench {

// What decode_png_with_lodepng passes to the inflate hook through custom_context.
struct InflateContext {
  size_t expected_bytes = 0;  // the filtered scanlines the header implies: the output's size
  std::string error;          // set by the hook when it fails, for the message
};

// lodepng's custom_zlib hook: inflates the zlib stream `in` (all IDAT data) into a buffer it
// allocates with malloc() (lodepng frees it); returns 0 on success.
using ZlibInflate = unsigned (*)(unsigned char** out, size_t* out_size, const unsigned char* in,
                                 size_t in_size, const LodePNGDecompressSettings* settings);

// ISA-L's inflate (io/png_isal_inflate.h) as such a hook.
unsigned inflate_hook_with_isal(unsigned char** out, size_t* out_size, const unsigned char* in,
                                size_t in_size, const LodePNGDecompressSettings* settings);

// As read_png documents, for its common layouts, with `inflate` (nullptr: lodepng's own).
// Throws InputError naming the file.
cv::Mat decode_png_with_lodepng(const PngSource& png, ZlibInflate inflate);

}  // namespace slamkit::bench
