#pragma once
// PNG decoding through lodepng with a pluggable inflate: lodepng parses the chunks and undoes
// the filters, the inflate function given (lodepng's custom_zlib hook) unpacks the image
// data. read_png plugs in ISA-L's (io/png_isal_inflate.h); the benchmark tries others.
#include <lodepng.h>

#include <opencv2/core.hpp>
#include <string>

#include "io/png_source.h"

namespace slamkit {

// What decode_png_with_lodepng passes to the inflate hook through custom_context.
struct InflateContext {
  size_t expected_bytes = 0;  // the filtered scanlines the header implies: the output's size
  std::string error;          // set by the hook when it fails, for the message
};

// lodepng's custom_zlib hook: inflates the zlib stream `in` (all IDAT data) into a buffer it
// allocates with malloc() (lodepng frees it); returns 0 on success.
using ZlibInflate = unsigned (*)(unsigned char** out, size_t* out_size, const unsigned char* in,
                                 size_t in_size, const LodePNGDecompressSettings* settings);

// The layouts it decodes: 8- or 16-bit grey, RGB or RGBA, not interlaced (TUM's and ours).
bool lodepng_decodes(const PngHeader& header);

// As read_png documents, with `inflate` (nullptr: lodepng's own). Throws InputError naming
// the file.
cv::Mat decode_png_with_lodepng(const PngSource& png, ZlibInflate inflate);

}  // namespace slamkit
