#pragma once
// The map's voxel grid, filled batch by batch: each voxel keeps the sums of the points that fell
// in it, so fusion holds memory per voxel (50-65 bytes), not per raw point. Written by hand:
// PCL's VoxelGrid filters a cloud held whole in memory (32 bytes a raw point: 12.7 million on
// synthetic desk 600), and merging per-batch grids gave centroids of centroids; PCL's octree
// centroid grid costs more per voxel and fills on one thread.
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "fusion/flat_hash_map.h"

namespace slamkit {

// A point placed in the grid: its voxel's key and where it lies inside the voxel (0..1 per axis).
struct BinnedPoint {
  uint64_t key = 0;
  Eigen::Vector3f offset = Eigen::Vector3f::Zero();
  cv::Vec3b bgr;
};

struct VoxelCentroid {
  Eigen::Vector3f position;
  cv::Vec3b bgr;  // mean colour, rounded
};

class VoxelMap {
 public:
  // leaf: voxel edge in metres. shards: independent tables, so that threads fill the grid side
  // by side, each its own shard.
  VoxelMap(float leaf, int shards);

  // The voxel of world point p; false when p lies more than 2^20 voxels from the origin on an
  // axis (10 km at 1 cm), which the key cannot hold.
  bool bin(const Eigen::Vector3f& p, const cv::Vec3b& bgr, BinnedPoint& out) const;

  // The shard that sums the voxel of `key`.
  int shard_of(uint64_t key) const { return int(key % uint64_t(shards_.size())); }

  // Adds `points`, whose voxels all belong to `shard`. One thread per shard at a time. Each
  // voxel is summed by its shard in the order the points come, so with the same batches in the
  // same order the sums are the same for any number of shards and threads.
  void add(int shard, const std::vector<BinnedPoint>& points);

  int shards() const { return int(shards_.size()); }
  size_t size() const;

  // The mean position and colour of the voxels, in ascending key order, leaving out those with
  // fewer occupied voxels among the 26 around them than neighbour_share x the median voxel's
  // count (0: none left out). Specks of noise and flying pixels have few or no neighbours; the
  // median makes the cut follow the map's density (a sparse map's surfaces have fewer).
  // Leaves the map empty: its tables are freed as soon as read, before the sort.
  std::vector<VoxelCentroid> take_centroids(double neighbour_share = 0);

 private:
  struct Sums {
    Eigen::Vector3f offset = Eigen::Vector3f::Zero();
    uint32_t blue = 0, green = 0, red = 0, count = 0;
  };
  struct KeyedCentroid {
    uint64_t key;
    VoxelCentroid centroid;
  };
  VoxelCentroid centroid(uint64_t key, const Sums& sums) const;
  // Every voxel's centroid, in ascending key order; empties the tables.
  std::vector<KeyedCentroid> take_sorted_centroids();

  float leaf_, inverse_leaf_;
  std::vector<FlatHashMap<Sums>> shards_;
};

}  // namespace slamkit
