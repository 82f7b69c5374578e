#pragma once
// The chunks of a PNG read by io/png_source.h: checked, and the image data gathered.
#include <vector>

#include "io/png_source.h"

namespace slamkit {

// Every chunk up to IEND whole and with the right CRC, or InputError naming the file and the
// chunk; then the data of the IDAT chunks joined in order (the zlib stream of the image). A
// bad CRC is an error in any chunk (libpng only warns for ancillary ones; TUM's frames and
// ours have none).
std::vector<unsigned char> checked_image_data(const PngSource& png);

}  // namespace slamkit
