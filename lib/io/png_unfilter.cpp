#include "io/png_unfilter.h"

#include <cstdint>
#include <cstdlib>
#include <vector>

namespace slamkit {
namespace {

enum Filter : unsigned char { kNone = 0, kSub = 1, kUp = 2, kAverage = 3, kPaeth = 4 };

// Sub with the pixel size fixed at compile time, so that the left pixel's bytes stay in
// registers instead of being read back from the row just written.
template <size_t kPixelBytes>
void undo_sub(unsigned char* row, size_t row_bytes) {
  unsigned char left[kPixelBytes] = {};
  for (size_t i = 0; i < row_bytes; i += kPixelBytes)
    for (size_t c = 0; c < kPixelBytes; ++c) row[i + c] = left[c] = uint8_t(row[i + c] + left[c]);
}

void undo_sub(unsigned char* row, size_t row_bytes, size_t pixel_bytes) {
  switch (pixel_bytes) {
    case 1:
      return undo_sub<1>(row, row_bytes);
    case 2:
      return undo_sub<2>(row, row_bytes);
    case 3:
      return undo_sub<3>(row, row_bytes);
    case 4:
      return undo_sub<4>(row, row_bytes);
    case 6:
      return undo_sub<6>(row, row_bytes);
    default:
      return undo_sub<8>(row, row_bytes);
  }
}

unsigned char paeth_predictor(int left, int above, int above_left) {
  const int estimate = left + above - above_left;
  const int to_left = std::abs(estimate - left), to_above = std::abs(estimate - above),
            to_above_left = std::abs(estimate - above_left);
  if (to_left <= to_above && to_left <= to_above_left) return uint8_t(left);
  return uint8_t(to_above <= to_above_left ? above : above_left);
}

}  // namespace

size_t unfilter_scanlines(unsigned char* scanlines, size_t height, size_t row_bytes,
                          size_t pixel_bytes) {
  const std::vector<unsigned char> zeros(row_bytes);  // "above" the first row
  const unsigned char* above = zeros.data();
  for (size_t r = 0; r < height; ++r) {
    unsigned char* const scanline = scanlines + r * (row_bytes + 1);
    unsigned char* const row = scanline + 1;
    const auto left = [&](size_t i) { return i < pixel_bytes ? 0 : row[i - pixel_bytes]; };
    const auto above_left = [&](size_t i) { return i < pixel_bytes ? 0 : above[i - pixel_bytes]; };
    switch (scanline[0]) {
      case kNone:
        break;
      case kSub:
        undo_sub(row, row_bytes, pixel_bytes);
        break;
      case kUp:
        for (size_t i = 0; i < row_bytes; ++i) row[i] = uint8_t(row[i] + above[i]);
        break;
      case kAverage:
        for (size_t i = 0; i < row_bytes; ++i) row[i] = uint8_t(row[i] + ((left(i) + above[i]) >> 1));
        break;
      case kPaeth:
        for (size_t i = 0; i < row_bytes; ++i)
          row[i] = uint8_t(row[i] + paeth_predictor(left(i), above[i], above_left(i)));
        break;
      default:
        return r;
    }
    above = row;
  }
  return height;
}

}  // namespace slamkit
