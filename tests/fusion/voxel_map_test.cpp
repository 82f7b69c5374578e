#include "fusion/voxel_map.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

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
  std::vector<BinnedPoint> binned;
  for (const auto& [p, bgr] : points) {
    BinnedPoint b;
    EXPECT_TRUE(voxels.bin(p, bgr, b));
    binned.push_back(b);
  }
  for (int shard = 0; shard < voxels.shards(); ++shard) voxels.add(shard, binned);
  return voxels.centroids(neighbour_share);
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
  const std::vector<VoxelCentroid> one = fill(points, 0.01f, 1), three = fill(points, 0.01f, 3);
  ASSERT_EQ(one.size(), three.size());
  for (size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].position, three[i].position) << i;  // bit for bit: same sums, same order
    EXPECT_EQ(one[i].bgr, three[i].bgr) << i;
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
