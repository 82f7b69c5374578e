#pragma once
// ISA-L's inflate as lodepng's custom_zlib hook (io/png_lodepng.h): Intel's hand-vectorised
// decoder, about twice as fast as zlib's on TUM frames.
#include "io/png_lodepng.h"

namespace slamkit {

// A ZlibInflate: the zlib header and the Adler-32 checksum are checked, as zlib checks them
// for libpng. Streams of 4 GiB or more (ISA-L counts in 32 bits) fail.
unsigned inflate_with_isal(unsigned char** out, size_t* out_size, const unsigned char* in,
                           size_t in_size, const LodePNGDecompressSettings* settings);

}  // namespace slamkit
