#include "fusion/voxel_neighbours.h"

#include <omp.h>

#include <algorithm>

#include "fusion/voxel_key.h"

namespace slamkit {
namespace {

// The counts of keys[begin, end). Around a voxel (x, y, z), the neighbours in row (dy, dz) are
// the keys from (x - 1, y + dy, z + dz) to (x + 1, y + dy, z + dz): one interval, whose bounds
// grow with the voxel's key. So one cursor per row walks the keys forward once, a merge instead
// of nine binary searches per voxel.
void count_span(const std::vector<uint64_t>& keys, size_t begin, size_t end, uint8_t* counts) {
  constexpr int kRows = 9;
  size_t cursor[kRows];
  bool placed[kRows] = {};  // a cursor is placed by binary search on its row's first use
  for (size_t i = begin; i < end; ++i) {
    // The biased indices, 0 .. kVoxelKeyMask, of the voxel.
    const uint64_t x = keys[i] & kVoxelKeyMask;
    const uint64_t y = (keys[i] >> kVoxelKeyBits) & kVoxelKeyMask;
    const uint64_t z = keys[i] >> (2 * kVoxelKeyBits);
    const uint64_t x_first = x > 0 ? x - 1 : x, x_last = x < kVoxelKeyMask ? x + 1 : x;
    int n = -1;  // the voxel itself, found in its own row
    int row = 0;
    for (uint64_t row_z = z - 1; row_z != z + 2; ++row_z)
      for (uint64_t row_y = y - 1; row_y != y + 2; ++row_y, ++row) {
        // Wrapped below 0 or past the mask: beyond the key's range, so empty.
        if (row_y > kVoxelKeyMask || row_z > kVoxelKeyMask) continue;
        const uint64_t row_key = (row_z << (2 * kVoxelKeyBits)) | (row_y << kVoxelKeyBits);
        const uint64_t first = row_key | x_first, last = row_key | x_last;
        size_t& c = cursor[row];
        if (!placed[row]) {
          c = size_t(std::lower_bound(keys.begin(), keys.end(), first) - keys.begin());
          placed[row] = true;
        }
        while (c < keys.size() && keys[c] < first) ++c;
        for (size_t k = c; k < keys.size() && keys[k] <= last; ++k) ++n;
      }
    counts[i] = uint8_t(n);
  }
}

}  // namespace

std::vector<uint8_t> count_occupied_neighbours(const std::vector<uint64_t>& keys) {
  std::vector<uint8_t> counts(keys.size());
#pragma omp parallel
  {
    const size_t threads = size_t(omp_get_num_threads()), thread = size_t(omp_get_thread_num());
    count_span(keys, keys.size() * thread / threads, keys.size() * (thread + 1) / threads,
               counts.data());
  }
  return counts;
}

}  // namespace slamkit
