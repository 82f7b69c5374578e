#pragma once
// Undoing PNG's row filters (the specification's section 9: None, Sub, Up, Average, Paeth).
// Written here because the decoders at hand undo Sub, the filter of every TUM frame, one byte
// at a time through memory: each byte waits for the store of the byte a pixel before it
// (lodepng: 5.5 % of `run`'s CPU on synthetic desk 600). Keeping a pixel's running sums in
// registers takes a fraction of that; the result is the same bytes.
#include <cstddef>

namespace slamkit {

// Undoes the filters of `height` scanlines in place. Each scanline is one filter-type byte
// followed by `row_bytes` filtered bytes, scanlines back to back; `pixel_bytes` is the bytes of
// one pixel (1, 2, 3, 4, 6 or 8: 8- or 16-bit samples, so row_bytes is a multiple of it).
// Returns the number of scanlines undone: fewer than `height` when that scanline's filter
// type is not one of the five, and the rest are left as they were.
size_t unfilter_scanlines(unsigned char* scanlines, size_t height, size_t row_bytes,
                          size_t pixel_bytes);

}  // namespace slamkit
