#pragma once
// A PNG file read whole into memory and its header checked, before any decoder sees it:
// the checks that every decoder of io/png_file.h shares.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamkit {

struct PngHeader {
  uint32_t width = 0, height = 0;
  int bit_depth = 0;    // 1, 2, 4, 8 or 16 bits per sample
  int colour_type = 0;  // the PNG code: 0 grey, 2 RGB, 3 palette, 4 grey+alpha, 6 RGBA
  bool interlaced = false;

  int channels() const;  // samples per pixel as stored (a palette index is one)
  // Bytes of filtered scanlines the image data must inflate to (without interlacing).
  double raw_bytes() const;
};

struct PngSource {
  std::string name;  // for messages
  std::vector<unsigned char> bytes;
  PngHeader header;
};

// Throws InputError naming the file when it cannot be read, is not a PNG, has a broken
// header, or declares more pixels than its data could hold (a few hostile header bytes must
// not make us allocate gigabytes).
PngSource load_png_source(const std::filesystem::path& path);

}  // namespace slamkit
