#pragma once
// How many of the 26 voxels around each occupied voxel are occupied, counted from the sorted
// keys alone (voxel_key.h), without a look-up table.
#include <cstdint>
#include <vector>

namespace slamkit {

// keys: distinct, ascending. Returns one count (0..26) per key. Neighbours beyond the key's
// range (2^20 voxels from the origin) count as empty. Runs on the OpenMP threads; the counts
// are the same at any number of threads.
std::vector<uint8_t> count_occupied_neighbours(const std::vector<uint64_t>& keys);

}  // namespace slamkit
