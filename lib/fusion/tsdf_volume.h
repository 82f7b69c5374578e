#pragma once
// A truncated signed distance field on a voxel hash (docs/method.md#map-fusion): blocks of
// 8 x 8 x 8 voxels allocated around the measured surfaces only, found through FlatHashMap by
// their grid index (voxel_key.h). Frames are integrated one after the other by projecting each
// voxel of the blocks near the frame's surface into its depth image (as KinectFusion and
// Open3D do), a block per thread: a voxel's value depends only on the frames and their order,
// so the field is the same at any thread count.
// Written by hand: PCL has no CPU TSDF, and Open3D's (Debian's libopen3d-dev) took 10 s for 200
// frames where this takes a tenth of that (docs/measurement-log/experiments.md).
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "fusion/flat_hash_map.h"
#include "fusion/tsdf_frame.h"

namespace slamkit {

// 8 bytes: the field of a room at 1 cm takes 10 to 20 million voxels.
struct TsdfVoxel {
  int16_t tsdf = 0;     // signed distance / truncation, in 1/32767 (positive: in front)
  uint16_t weight = 0;  // sum of the measurements' weights (tsdf_frame.h's units); 0 = never seen
  std::array<uint8_t, 3> rgb{};  // weighted mean colour
};

constexpr int kTsdfBlockSide = 8;
constexpr int kTsdfBlockVoxels = kTsdfBlockSide * kTsdfBlockSide * kTsdfBlockSide;

struct TsdfBlock {
  Eigen::Array3i index = Eigen::Array3i::Zero();  // block grid index (voxel index / 8)
  std::array<TsdfVoxel, kTsdfBlockVoxels> voxels{};  // x fastest, then y, then z

  static int voxel_at(int x, int y, int z) {
    return x + kTsdfBlockSide * (y + kTsdfBlockSide * z);
  }
};

inline float tsdf_value(const TsdfVoxel& v) { return float(v.tsdf) / 32767.0f; }
inline float tsdf_weight(const TsdfVoxel& v) { return float(v.weight) / kTsdfWeightUnits; }

class TsdfVolume {
 public:
  TsdfVolume(float voxel_size, float truncation);

  // Adds the frames, seen from their poses, in their order: allocates the blocks within the
  // truncation of each frame's surface, then updates each block's voxels in view of each frame
  // that allocated it, frame after frame. Runs on the OpenMP threads, a block per thread (so a
  // block stays in cache over the batch); the result is that of one frame at a time.
  void integrate(const std::vector<const TsdfFrame*>& frames,
                 const std::vector<Eigen::Isometry3d>& T_w_c);
  void integrate(const TsdfFrame& frame, const Eigen::Isometry3d& T_w_c) {
    integrate(std::vector<const TsdfFrame*>{&frame}, {T_w_c});
  }

  // Blocks in the order they were allocated (the same for any thread count).
  const std::vector<std::unique_ptr<TsdfBlock>>& blocks() const { return blocks_; }
  // The block with this grid index, or null.
  const TsdfBlock* find(const Eigen::Array3i& index) const;
  // Its position in blocks(), or -1.
  long ordinal(const Eigen::Array3i& index) const;
  float voxel_size() const { return voxel_size_; }
  float truncation() const { return truncation_; }
  size_t bytes() const;

 private:
  std::vector<uint64_t> block_keys_near_surface(const TsdfFrame& frame,
                                                const Eigen::Isometry3d& T_w_c) const;
  void update(TsdfBlock& block, const TsdfFrame& frame, const Eigen::Isometry3f& T_c_w) const;

  float voxel_size_, truncation_, block_size_;
  FlatHashMap<uint32_t> index_;  // block key -> position in blocks_ + 1
  std::vector<std::unique_ptr<TsdfBlock>> blocks_;
};

}  // namespace slamkit
