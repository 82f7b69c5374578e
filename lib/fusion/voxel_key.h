#pragma once
// A voxel's key: its three grid indices, each biased by 2^20 into 21 bits, x in the lowest bits
// and z in the highest. Ascending keys so run along x within a row of fixed (y, z), the rows in
// y then z order.
#include <Eigen/Core>
#include <cstdint>

namespace slamkit {

constexpr int kVoxelKeyBits = 21;  // per axis
constexpr int64_t kVoxelKeyBias = int64_t(1) << (kVoxelKeyBits - 1);
constexpr uint64_t kVoxelKeyMask = (uint64_t(1) << kVoxelKeyBits) - 1;

// The index must lie within -2^20 .. 2^20 - 1 on every axis (voxel_index_in_range).
inline uint64_t voxel_key(const Eigen::Array3i& index) {
  uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis)
    key |= uint64_t(index[axis] + kVoxelKeyBias) << (kVoxelKeyBits * axis);
  return key;
}

inline Eigen::Array3i voxel_index(uint64_t key) {
  Eigen::Array3i index;
  for (int axis = 0; axis < 3; ++axis)
    index[axis] = int(int64_t((key >> (kVoxelKeyBits * axis)) & kVoxelKeyMask) - kVoxelKeyBias);
  return index;
}

inline bool voxel_index_in_range(const Eigen::Array3i& index) {
  return (index >= -int(kVoxelKeyBias)).all() && (index < int(kVoxelKeyBias)).all();
}

}  // namespace slamkit
