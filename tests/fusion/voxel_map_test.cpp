#include "fusion/voxel_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <tuple>

namespace slamkit {
namespace {

// Points scattered over a few voxels, each with a colour.
std::vector<std::pair<Eigen::Vector3f, cv::Vec3b>> scattered_points(size_t count) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-0.035f, 0.025f);
  std::uniform_int_distribution<int> channel(0, 255);
  std::vector<std::pair<Eigen::Vector3f, cv::Vec3b>> points;
  for (size_t i = 0; i < count; ++i)
    points.push_back(
        {{coordinate(rng), coordinate(rng), coordinate(rng)},
         cv::Vec3b(uint8_t(channel(rng)), uint8_t(channel(rng)), uint8_t(channel(rng)))});
  return points;
}

std::vector<VoxelCentroid> fill(const std::vector<std::pair<Eigen::Vector3f, cv::Vec3b>>& points,
                                float leaf, int shards, double neighbour_share = 0) {
  VoxelMap voxels(leaf, shards);
  std::vector<std::vector<BinnedPoint>> binned(size_t(voxels.shards()));
  for (const auto& [p, bgr] : points) {
    BinnedPoint b;
    EXPECT_TRUE(voxels.bin(p, bgr, b));
    binned[size_t(voxels.shard_of(b.key))].push_back(b);
  }
  for (int shard = 0; shard < voxels.shards(); ++shard) voxels.add(shard, binned[size_t(shard)]);
  return voxels.take_centroids(neighbour_share);
}

TEST(VoxelMap, EachCentroidIsTheMeanOfItsVoxelsPoints) {
  const float leaf = 0.01f;
  const auto points = scattered_points(5000);
  // The reference: points grouped by floor(p / leaf), as PCL's VoxelGrid groups them.
  std::map<std::tuple<int, int, int>, std::vector<size_t>> groups;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3f cell = (points[i].first.array() * (1.0f / leaf)).floor();
    groups[{int(cell.z()), int(cell.y()), int(cell.x())}].push_back(i);  // z major, as the key
  }
  const std::vector<VoxelCentroid> centroids = fill(points, leaf, 1);
  ASSERT_EQ(centroids.size(), groups.size());
  size_t k = 0;
  for (const auto& [cell, members] : groups) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Vector3d colour = Eigen::Vector3d::Zero();
    for (size_t i : members) {
      mean += points[i].first.cast<double>();
      for (int c = 0; c < 3; ++c) colour[c] += points[i].second[c];
    }
    mean /= double(members.size());
    colour /= double(members.size());
    EXPECT_LT((centroids[k].position.cast<double>() - mean).norm(), 1e-6) << k;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(centroids[k].bgr[c], std::lround(colour[c])) << k;
    ++k;
  }
}

TEST(VoxelMap, ShardsChangeNothing) {
  const auto points = scattered_points(3000);
  for (const double neighbour_share : {0.0, 0.3}) {
    const std::vector<VoxelCentroid> one = fill(points, 0.01f, 1, neighbour_share),
                                     three = fill(points, 0.01f, 3, neighbour_share);
    ASSERT_EQ(one.size(), three.size());
    for (size_t i = 0; i < one.size(); ++i) {
      EXPECT_EQ(one[i].position, three[i].position) << i;  // bit for bit: same sums, same order
      EXPECT_EQ(one[i].bgr, three[i].bgr) << i;
    }
  }
}

TEST(VoxelMap, TheNeighbourCutKeepsWhatABruteForceCountKeeps) {
  // A sparse cloud, so that voxels have from none to many occupied neighbours.
  const float leaf = 0.01f;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-0.06f, 0.06f);
  std::vector<std::pair<Eigen::Vector3f, cv::Vec3b>> points;
  std::set<std::tuple<int, int, int>> cells;
  for (int i = 0; i < 600; ++i) {
    const Eigen::Vector3f p(coordinate(rng), coordinate(rng), coordinate(rng));
    points.push_back({p, {}});
    const Eigen::Array3i cell = (p.array() / leaf).floor().cast<int>();
    cells.insert({cell.x(), cell.y(), cell.z()});
  }
  std::vector<int> counts;
  for (const auto& [x, y, z] : cells) {
    int n = 0;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          n += (dx || dy || dz) && cells.count({x + dx, y + dy, z + dz});
    counts.push_back(n);
  }
  std::vector<int> sorted = counts;
  std::sort(sorted.begin(), sorted.end());
  const int median = sorted[sorted.size() / 2];
  ASSERT_GE(median, 2);
  for (const double share : {0.5, 1.0}) {
    const long least = std::lround(share * median);
    const size_t kept =
        size_t(std::count_if(counts.begin(), counts.end(), [&](int n) { return n >= least; }));
    ASSERT_LT(kept, cells.size()) << share;  // the cut does leave some out
    EXPECT_EQ(fill(points, leaf, 2, share).size(), kept) << share;
  }
}

TEST(VoxelMap, IsolatedVoxelsAreLeftOutAndASurfaceKept) {
  const float leaf = 0.01f;
  std::vector<std::pair<Eigen::Vector3f, cv::Vec3b>> points;
  for (int u = 0; u < 20; ++u)  // a 20 x 20 voxel patch of the plane z = 0.005
    for (int v = 0; v < 20; ++v)
      points.push_back({{0.005f + u * leaf, 0.005f + v * leaf, 0.005f}, {}});
  points.push_back({{0.5f, 0.5f, 0.5f}, {}});        // a speck of noise, far off
  points.push_back({{0.105f, 0.105f, 0.035f}, {}});  // two voxels off the plane: no neighbour
  EXPECT_EQ(fill(points, leaf, 2, 0).size(), 402u);
  // Inside the patch a voxel has 8 neighbours (the median), on its edge 5, at its corners 3.
  EXPECT_EQ(fill(points, leaf, 2, 0.3).size(), 400u);       // fewer than 2.4 -> 2
  EXPECT_EQ(fill(points, leaf, 2, 0.5).size(), 400u - 4);   // fewer than 4
  EXPECT_EQ(fill(points, leaf, 2, 0.7).size(), 18u * 18u);  // fewer than 5.6 -> 6
  EXPECT_EQ(fill(points, leaf, 2, 1.0).size(), 18u * 18u);  // fewer than 8
  // The cut follows the median: a patch sampled at every other voxel has no voxel with a
  // neighbour, so none is left out.
  std::vector<std::pair<Eigen::Vector3f, cv::Vec3b>> sparse;
  for (int u = 0; u < 20; u += 2)
    for (int v = 0; v < 20; v += 2)
      sparse.push_back({{0.005f + u * leaf, 0.005f + v * leaf, 0.005f}, {}});
  EXPECT_EQ(fill(sparse, leaf, 2, 0.3).size(), 100u);
}

TEST(VoxelMap, PointsBeyondTheKeysRangeAreRefused) {
  const VoxelMap voxels(0.01f, 1);
  BinnedPoint b;
  EXPECT_TRUE(voxels.bin({10000.0f, -10000.0f, 0}, {}, b));  // 10 km: 10^6 voxels, within 2^20
  EXPECT_FALSE(voxels.bin({20000.0f, 0, 0}, {}, b));
  EXPECT_FALSE(voxels.bin({0, 0, -20000.0f}, {}, b));
}

}  // namespace
}  // namespace slamkit
