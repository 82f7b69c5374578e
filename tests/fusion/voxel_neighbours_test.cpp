#include "fusion/voxel_neighbours.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <random>
#include <set>

#include "fusion/voxel_key.h"

namespace slamkit {
namespace {

// The count by its definition: each of the 26 voxels around, looked up in a set.
std::vector<uint8_t> brute_force_counts(const std::vector<uint64_t>& keys) {
  const std::set<uint64_t> occupied(keys.begin(), keys.end());
  std::vector<uint8_t> counts;
  for (uint64_t key : keys) {
    const Eigen::Array3i centre = voxel_index(key);
    int n = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Eigen::Array3i index = centre + Eigen::Array3i(dx, dy, dz);
          if ((dx || dy || dz) && voxel_index_in_range(index))
            n += int(occupied.count(voxel_key(index)));
        }
    counts.push_back(uint8_t(n));
  }
  return counts;
}

std::vector<uint64_t> sorted_unique(std::vector<uint64_t> keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

TEST(VoxelNeighbours, MatchBruteForceInADenseBlob) {
  // Voxels filled at random in a 12^3 box: every count from 0 to 26 is likely.
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coordinate(-6, 5);
  std::vector<uint64_t> keys;
  for (int i = 0; i < 1200; ++i)
    keys.push_back(voxel_key({coordinate(rng), coordinate(rng), coordinate(rng)}));
  keys = sorted_unique(keys);
  const std::vector<uint8_t> expected = brute_force_counts(keys);
  const int default_threads = omp_get_max_threads();
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(count_occupied_neighbours(keys), expected) << threads << " threads";
  }
  omp_set_num_threads(default_threads);
  EXPECT_GT(*std::max_element(expected.begin(), expected.end()), 20);
}

TEST(VoxelNeighbours, MatchBruteForceAtTheEdgesOfTheKeysRange) {
  // Neighbours past the range must not wrap into the next row or layer of keys.
  const int lo = -int(kVoxelKeyBias), hi = int(kVoxelKeyBias) - 1;
  std::vector<uint64_t> keys;
  for (const int x : {lo, lo + 1, hi - 1, hi})
    for (const int y : {lo, lo + 1, 0, hi - 1, hi})
      for (const int z : {lo, lo + 1, 0, 1, hi - 1, hi}) keys.push_back(voxel_key({x, y, z}));
  keys = sorted_unique(keys);
  EXPECT_EQ(count_occupied_neighbours(keys), brute_force_counts(keys));
}

TEST(VoxelNeighbours, NoVoxelsNoCounts) { EXPECT_TRUE(count_occupied_neighbours({}).empty()); }

}  // namespace
}  // namespace slamkit
