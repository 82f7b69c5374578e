#include "fusion/tsdf_volume.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "fusion/voxel_key.h"

namespace slamkit {
namespace {

// Blocks are allocated from every 4th sample in u and v (8 raw pixels at the default stride:
// 15 mm at 1 m, 46 mm at 3 m, where a block is 8 cm wide).
constexpr int kAllocationStride = 4;

}  // namespace

TsdfVolume::TsdfVolume(float voxel_size, float truncation)
    : voxel_size_(voxel_size),
      truncation_(truncation),
      block_size_(voxel_size * kTsdfBlockSide) {}

const TsdfBlock* TsdfVolume::find(const Eigen::Array3i& index) const {
  const long at = ordinal(index);
  return at < 0 ? nullptr : blocks_[size_t(at)].get();
}

long TsdfVolume::ordinal(const Eigen::Array3i& index) const {
  if (!voxel_index_in_range(index)) return -1;
  const uint32_t* at = index_.find(voxel_key(index));
  return at ? long(*at) - 1 : -1;
}

size_t TsdfVolume::bytes() const { return blocks_.size() * sizeof(TsdfBlock); }

std::vector<uint64_t> TsdfVolume::block_keys_near_surface(const TsdfFrame& frame,
                                                          const Eigen::Isometry3d& T_w_c) const {
  const SampleIntrinsics& in = frame.intrinsics;
  const Eigen::Isometry3f pose = T_w_c.cast<float>();
  // Points along each ray from truncation before the surface to truncation behind it, at most
  // half a block apart, so that every block the segment crosses is hit.
  const int steps = int(std::ceil(2 * truncation_ / (0.5f * block_size_)));
  const float inverse_block = 1.0f / block_size_;
  const int rows = (in.height + kAllocationStride - 1) / kAllocationStride;
  auto per_row = std::vector<std::vector<uint64_t>>(size_t(rows));
#pragma omp parallel for schedule(static)
  for (int r = 0; r < rows; ++r) {
    const int j = r * kAllocationStride;
    std::vector<uint64_t>& keys = per_row[size_t(r)];
    uint64_t last = ~uint64_t(0);
    for (int i = 0; i < in.width; i += kAllocationStride) {
      const float d = frame.depth[size_t(j) * size_t(in.width) + size_t(i)];
      if (d == 0) continue;
      const Eigen::Vector3f ray((float(i) - in.cx) / in.fx, (float(j) - in.cy) / in.fy, 1.0f);
      for (int s = 0; s <= steps; ++s) {
        const float z = d - truncation_ + 2 * truncation_ * float(s) / float(steps);
        if (z <= 0) continue;
        const Eigen::Array3i block =
            ((pose * (ray * z)).array() * inverse_block).floor().cast<int>();
        if (!voxel_index_in_range(block)) continue;
        const uint64_t key = voxel_key(block);
        if (key != last) keys.push_back(key);  // neighbouring rays mostly hit the same blocks
        last = key;
      }
    }
  }
  std::vector<uint64_t> keys;
  for (const std::vector<uint64_t>& row : per_row) keys.insert(keys.end(), row.begin(), row.end());
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

void TsdfVolume::integrate(const std::vector<const TsdfFrame*>& frames,
                           const std::vector<Eigen::Isometry3d>& T_w_c) {
  std::vector<std::vector<uint64_t>> keys(frames.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long f = 0; f < long(frames.size()); ++f)
    keys[size_t(f)] = block_keys_near_surface(*frames[size_t(f)], T_w_c[size_t(f)]);
  // Allocation frame by frame in ascending key order, on one thread: the blocks' order does
  // not depend on the threads. Then each block's frames, in frame order.
  std::vector<std::pair<uint32_t, uint32_t>> block_frame;  // (block, frame)
  for (size_t f = 0; f < frames.size(); ++f) {
    for (const uint64_t key : keys[f]) {
      uint32_t& slot = index_[key];
      if (slot == 0) {
        blocks_.push_back(std::make_unique<TsdfBlock>());
        blocks_.back()->index = voxel_index(key);
        slot = uint32_t(blocks_.size());
      }
      block_frame.emplace_back(slot - 1, uint32_t(f));
    }
    keys[f] = {};
  }
  std::sort(block_frame.begin(), block_frame.end());
  std::vector<size_t> group_starts;
  for (size_t k = 0; k < block_frame.size(); ++k)
    if (k == 0 || block_frame[k].first != block_frame[k - 1].first) group_starts.push_back(k);
  group_starts.push_back(block_frame.size());
  std::vector<Eigen::Isometry3f> T_c_w;
  for (const Eigen::Isometry3d& pose : T_w_c) T_c_w.push_back(pose.inverse().cast<float>());
  const long groups = long(group_starts.size()) - 1;
#pragma omp parallel for schedule(dynamic, 8)
  for (long g = 0; g < groups; ++g)
    for (size_t k = group_starts[size_t(g)]; k < group_starts[size_t(g) + 1]; ++k)
      update(*blocks_[block_frame[k].first], *frames[block_frame[k].second],
             T_c_w[block_frame[k].second]);
}

void TsdfVolume::update(TsdfBlock& block, const TsdfFrame& frame,
                        const Eigen::Isometry3f& T_c_w) const {
  const SampleIntrinsics& in = frame.intrinsics;
  const Eigen::Matrix3f step = T_c_w.linear() * voxel_size_;
  // The centre of the block's first voxel in the camera's frame.
  const Eigen::Vector3f first =
      T_c_w * ((block.index.cast<float>() * block_size_).matrix() +
               Eigen::Vector3f::Constant(0.5f * voxel_size_));
  const float inverse_truncation = 1.0f / truncation_;
  const float width = float(in.width), height = float(in.height);
  for (int z = 0; z < kTsdfBlockSide; ++z)
    for (int y = 0; y < kTsdfBlockSide; ++y) {
      const Eigen::Vector3f row = first + step.col(2) * float(z) + step.col(1) * float(y);
      // The row's eight projections first, without branches (the compiler vectorises this
      // loop), then the updates: the nearest sample, or -1 outside the image or behind the
      // camera. int() truncates, so negative coordinates are refused first.
      std::array<float, kTsdfBlockSide> depth_of;
      std::array<int32_t, kTsdfBlockSide> sample_of;
      for (int x = 0; x < kTsdfBlockSide; ++x) {
        const float px = row.x() + step(0, 0) * float(x), py = row.y() + step(1, 0) * float(x),
                    pz = row.z() + step(2, 0) * float(x);
        const float inverse_z = 1.0f / pz;
        const float u = in.fx * px * inverse_z + in.cx + 0.5f;
        const float v = in.fy * py * inverse_z + in.cy + 0.5f;
        const bool inside = pz > 0 && u >= 0 && v >= 0 && u < width && v < height;
        sample_of[size_t(x)] = inside ? int32_t(v) * in.width + int32_t(u) : -1;
        depth_of[size_t(x)] = pz;
      }
      TsdfVoxel* voxel = &block.voxels[size_t(TsdfBlock::voxel_at(0, y, z))];
      for (int x = 0; x < kTsdfBlockSide; ++x, ++voxel) {
        if (sample_of[size_t(x)] < 0) continue;
        const size_t k = size_t(sample_of[size_t(x)]);
        const float d = frame.depth[k];
        if (d == 0) continue;
        const float sdf = d - depth_of[size_t(x)];  // along the optical axis, as KinectFusion's
        if (sdf < -truncation_) continue;           // hidden behind the surface
        const float measured = std::min(1.0f, sdf * inverse_truncation);
        const uint32_t w = frame.weight[k];
        const uint32_t before = voxel->weight, total = before + w;
        // The new measurement's share of the running means.
        const float share = float(w) / float(total);
        const float mean = tsdf_value(*voxel) + (measured - tsdf_value(*voxel)) * share;
        voxel->tsdf = int16_t(mean * 32767.0f + (mean < 0 ? -0.5f : 0.5f));
        const uint8_t* rgb = &frame.rgb[3 * k];
        for (size_t c = 0; c < 3; ++c)
          voxel->rgb[c] = uint8_t(float(voxel->rgb[c]) +
                                  (float(rgb[c]) - float(voxel->rgb[c])) * share + 0.5f);
        voxel->weight = uint16_t(std::min<uint32_t>(total, 65535));
      }
    }
}

}  // namespace slamkit
