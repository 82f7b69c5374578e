#include "io/png_chunks.h"

#include <isa-l/crc.h>

#include <cstdint>
#include <string>

#include "core/error.h"

namespace slamkit {
namespace {

uint32_t big_endian_32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

}  // namespace

std::vector<unsigned char> checked_image_data(const PngSource& png) {
  std::vector<unsigned char> image_data;
  const unsigned char* const end = png.bytes.data() + png.bytes.size();
  const unsigned char* chunk = png.bytes.data() + 8;  // after the signature
  while (end - chunk >= 12) {  // length, type, CRC
    const std::string type(reinterpret_cast<const char*>(chunk + 4), 4);
    const size_t length = big_endian_32(chunk);
    if (length > size_t(end - chunk) - 12)
      throw_input_error(png.name,
                        "cannot decode image: the file ends inside its " + type + " chunk");
    // ISA-L's CRC-32 (PCLMUL): the same as zlib's crc32, several times faster.
    if (crc32_gzip_refl(0, chunk + 4, length + 4) != big_endian_32(chunk + 8 + length))
      throw_input_error(png.name, "cannot decode image: CRC error in the " + type + " chunk");
    if (type == "IEND") {
      if (image_data.empty())
        throw_input_error(png.name, "cannot decode image: no image data (IDAT chunk)");
      return image_data;
    }
    if (type == "IDAT") image_data.insert(image_data.end(), chunk + 8, chunk + 8 + length);
    chunk += 12 + length;
  }
  throw_input_error(png.name, "cannot decode image: the file ends before its IEND chunk");
}

}  // namespace slamkit
