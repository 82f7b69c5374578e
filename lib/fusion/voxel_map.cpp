#include "fusion/voxel_map.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace slamkit {
namespace {

// A key packs the three voxel indices, each biased by 2^20 into 21 bits.
constexpr int kBits = 21;
constexpr int64_t kBias = int64_t(1) << (kBits - 1);
constexpr uint64_t kMask = (uint64_t(1) << kBits) - 1;

uint64_t pack(const Eigen::Array3i& index) {
  uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) key |= uint64_t(index[axis] + kBias) << (kBits * axis);
  return key;
}

Eigen::Array3i unpack(uint64_t key) {
  Eigen::Array3i index;
  for (int axis = 0; axis < 3; ++axis)
    index[axis] = int(int64_t((key >> (kBits * axis)) & kMask) - kBias);
  return index;
}

bool in_range(const Eigen::Array3i& index) {
  return (index >= -int(kBias)).all() && (index < int(kBias)).all();
}

}  // namespace

VoxelMap::VoxelMap(float leaf, int shards)
    : leaf_(leaf), inverse_leaf_(1.0f / leaf), shards_(size_t(std::max(1, shards))) {}

bool VoxelMap::bin(const Eigen::Vector3f& p, const cv::Vec3b& bgr, BinnedPoint& out) const {
  const Eigen::Array3f scaled = p.array() * inverse_leaf_;
  const Eigen::Array3f corner = scaled.floor();
  if (!((corner >= -float(kBias)).all() && (corner < float(kBias)).all())) return false;
  out.key = pack(corner.cast<int>());
  out.offset = (scaled - corner).matrix();
  out.bgr = bgr;
  return true;
}

void VoxelMap::add(int shard, const std::vector<BinnedPoint>& points) {
  std::unordered_map<uint64_t, Sums>& table = shards_[size_t(shard)];
  for (const BinnedPoint& p : points) {
    if (shard_of(p.key) != shard) continue;
    Sums& s = table[p.key];
    s.offset += p.offset;
    s.blue += p.bgr[0];
    s.green += p.bgr[1];
    s.red += p.bgr[2];
    ++s.count;
  }
}

size_t VoxelMap::size() const {
  size_t n = 0;
  for (const auto& table : shards_) n += table.size();
  return n;
}

std::vector<uint64_t> VoxelMap::sorted_keys() const {
  std::vector<uint64_t> keys;
  keys.reserve(size());
  for (const auto& table : shards_)
    for (const auto& [key, sums] : table) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  return keys;
}

int VoxelMap::occupied_neighbours(uint64_t key) const {
  const Eigen::Array3i centre = unpack(key);
  int n = 0;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Eigen::Array3i index = centre + Eigen::Array3i(dx, dy, dz);
        if ((dx != 0 || dy != 0 || dz != 0) && in_range(index)) n += occupied(pack(index));
      }
  return n;
}

std::vector<VoxelCentroid> VoxelMap::centroids(double neighbour_share) const {
  const std::vector<uint64_t> keys = sorted_keys();
  std::vector<uint8_t> kept(keys.size(), 1);
  if (neighbour_share > 0 && !keys.empty()) {
    std::vector<uint8_t> neighbours(keys.size());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < long(keys.size()); ++i)
      neighbours[size_t(i)] = uint8_t(occupied_neighbours(keys[size_t(i)]));
    std::vector<uint8_t> sorted = neighbours;
    std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
    const long least = std::lround(neighbour_share * sorted[sorted.size() / 2]);
    for (size_t i = 0; i < keys.size(); ++i) kept[i] = neighbours[i] >= least;
  }
  std::vector<VoxelCentroid> out;
  out.reserve(size_t(std::count(kept.begin(), kept.end(), 1)));
  for (size_t i = 0; i < keys.size(); ++i) {
    if (!kept[i]) continue;
    const Sums& s = shards_[size_t(shard_of(keys[i]))].at(keys[i]);
    const Eigen::Vector3f corner = unpack(keys[i]).cast<float>().matrix();
    const auto mean = [&](uint32_t sum) { return uint8_t(std::lround(double(sum) / s.count)); };
    out.push_back({(corner + s.offset / float(s.count)) * leaf_,
                   cv::Vec3b(mean(s.blue), mean(s.green), mean(s.red))});
  }
  return out;
}

}  // namespace slamkit
