#include "fusion/voxel_map.h"

#include <algorithm>
#include <cmath>

#include "fusion/voxel_key.h"
#include "fusion/voxel_neighbours.h"

namespace slamkit {

VoxelMap::VoxelMap(float leaf, int shards)
    : leaf_(leaf), inverse_leaf_(1.0f / leaf), shards_(size_t(std::max(1, shards))) {}

bool VoxelMap::bin(const Eigen::Vector3f& p, const cv::Vec3b& bgr, BinnedPoint& out) const {
  const Eigen::Array3f scaled = p.array() * inverse_leaf_;
  const Eigen::Array3f corner = scaled.floor();
  if (!((corner >= -float(kVoxelKeyBias)).all() && (corner < float(kVoxelKeyBias)).all()))
    return false;
  out.key = voxel_key(corner.cast<int>());
  out.offset = (scaled - corner).matrix();
  out.bgr = bgr;
  return true;
}

void VoxelMap::add(int shard, const std::vector<BinnedPoint>& points) {
  FlatHashMap<Sums>& table = shards_[size_t(shard)];
  // Neighbouring pixels often fall in the same voxel: its sums are then at hand.
  Sums* s = nullptr;
  uint64_t key = 0;
  for (const BinnedPoint& p : points) {
    if (!s || p.key != key) {
      key = p.key;
      s = &table[key];
    }
    s->offset += p.offset;
    s->blue += p.bgr[0];
    s->green += p.bgr[1];
    s->red += p.bgr[2];
    ++s->count;
  }
}

size_t VoxelMap::size() const {
  size_t n = 0;
  for (const auto& table : shards_) n += table.size();
  return n;
}

VoxelCentroid VoxelMap::centroid(uint64_t key, const Sums& s) const {
  const Eigen::Vector3f corner = voxel_index(key).cast<float>().matrix();
  const auto mean = [&](uint32_t sum) { return uint8_t(std::lround(double(sum) / s.count)); };
  return {(corner + s.offset / float(s.count)) * leaf_,
          cv::Vec3b(mean(s.blue), mean(s.green), mean(s.red))};
}

std::vector<VoxelMap::KeyedCentroid> VoxelMap::take_sorted_centroids() {
  std::vector<KeyedCentroid> voxels;
  voxels.reserve(size());
  for (FlatHashMap<Sums>& table : shards_) {
    table.for_each([&](uint64_t key, const Sums& sums) {
      voxels.push_back({key, centroid(key, sums)});
    });
    table = {};
  }
  std::sort(voxels.begin(), voxels.end(),
            [](const KeyedCentroid& a, const KeyedCentroid& b) { return a.key < b.key; });
  return voxels;
}

std::vector<VoxelCentroid> VoxelMap::take_centroids(double neighbour_share) {
  const std::vector<KeyedCentroid> voxels = take_sorted_centroids();
  std::vector<uint8_t> kept(voxels.size(), 1);
  if (neighbour_share > 0 && !voxels.empty()) {
    std::vector<uint64_t> keys(voxels.size());
    for (size_t i = 0; i < voxels.size(); ++i) keys[i] = voxels[i].key;
    const std::vector<uint8_t> neighbours = count_occupied_neighbours(keys);
    std::vector<uint8_t> sorted = neighbours;
    std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
    const long least = std::lround(neighbour_share * sorted[sorted.size() / 2]);
    for (size_t i = 0; i < voxels.size(); ++i) kept[i] = neighbours[i] >= least;
  }
  std::vector<VoxelCentroid> out;
  out.reserve(size_t(std::count(kept.begin(), kept.end(), 1)));
  for (size_t i = 0; i < voxels.size(); ++i)
    if (kept[i]) out.push_back(voxels[i].centroid);
  return out;
}

}  // namespace slamkit
