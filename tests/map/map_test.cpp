#include "map/map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace slamkit {
namespace {

int nonzero_bytes(const Descriptor& d) {
  return int(std::count_if(d.begin(), d.end(), [](uint8_t byte) { return byte != 0; }));
}

// A keyframe at `T_w_c` with `n` keypoints at pixel (100 + i, 200), octave `octave`, depth 2 m,
// descriptors all zero unless set later.
Keyframe keyframe_with(size_t n, size_t frame_index,
                       const Eigen::Isometry3d& T_w_c = Eigen::Isometry3d::Identity(),
                       int octave = 0) {
  Keyframe k;
  k.frame_index = frame_index;
  k.T_w_c = T_w_c;
  for (size_t i = 0; i < n; ++i) {
    cv::KeyPoint kp(cv::Point2f(100.0f + float(i), 200.0f), 31.0f);
    kp.octave = octave;
    k.keypoints.push_back(kp);
    k.undistorted.emplace_back(100.0 + double(i), 200.0);
    k.depths.push_back(2.0f);
  }
  k.descriptors = cv::Mat(int(n), 32, CV_8U, cv::Scalar(0));
  k.point_ids.assign(n, -1);
  return k;
}

// A map of `keyframes` keyframes where keyframe k observes points [0, shared[k]) of keyframe 0.
Map map_sharing(const std::vector<int>& shared, int min_shared = 15) {
  Map map(PyramidGeometry{}, min_shared);
  const int n = 40;
  map.add_keyframe(keyframe_with(n, 0));
  for (int i = 0; i < n; ++i) map.add_point(Eigen::Vector3d(0.01 * i, 0, 2), 0, i);
  map.update_connections(0);
  for (size_t k = 0; k < shared.size(); ++k) {
    Keyframe kf = keyframe_with(n, k + 1);
    for (int i = 0; i < shared[k]; ++i) kf.point_ids[size_t(i)] = i;
    const int id = map.add_keyframe(std::move(kf));
    map.update_connections(id);
  }
  return map;
}

TEST(Map, ObservationsLinkKeypointsAndPointsBothWays) {
  Map map = map_sharing({20});
  EXPECT_EQ(map.point(3).num_observations(), 2);
  EXPECT_EQ(map.point(30).num_observations(), 1);
  EXPECT_EQ(map.keyframe(1).point_ids[3], 3);
  EXPECT_EQ(map.keyframe(1).point_ids[30], -1);
  map.erase_observation(3, 1);
  EXPECT_EQ(map.keyframe(1).point_ids[3], -1);
  EXPECT_EQ(map.point(3).num_observations(), 1);
  EXPECT_FALSE(map.point(3).bad);
  map.erase_observation(3, 0);  // the last observation: the point is gone
  EXPECT_TRUE(map.point(3).bad);
  EXPECT_EQ(map.num_good_points(), 39);
}

TEST(Map, CovisibilityLinksKeyframesSharingFifteenPointsWithTheirWeights) {
  // Keyframes 1..3 share 20, 10 and 16 points with keyframe 0 (and so with each other).
  const Map map = map_sharing({20, 10, 16});
  EXPECT_EQ(map.keyframe(0).shared_points.at(1), 20);
  EXPECT_EQ(map.keyframe(0).shared_points.at(2), 10);
  EXPECT_EQ(map.keyframe(3).shared_points.at(1), 16);
  EXPECT_EQ(map.keyframe(3).shared_points.at(2), 10);
  // Best first; keyframe 2's 10 shared points are below 15.
  EXPECT_EQ(map.keyframe(0).covisible, (std::vector<int>{1, 3}));
  EXPECT_EQ(map.keyframe(1).covisible, (std::vector<int>{0, 3}));
  // With no neighbour reaching 15, the best one is linked alone (ORB-SLAM2).
  EXPECT_EQ(map.keyframe(2).covisible.size(), 1u);
  EXPECT_EQ(map.best_covisible(0, 1), (std::vector<int>{1}));
}

TEST(Map, NeighbourListsStaySortedAsLinksChange) {
  // Keyframes observing random subsets of 60 points, some later losing points: every list
  // must equal the one sorted from scratch (weight >= 15 best first, then lowest index; the
  // best alone when none reaches 15).
  Map map(PyramidGeometry{}, 15);
  std::mt19937 rng(3);
  map.add_keyframe(keyframe_with(60, 0));
  for (int i = 0; i < 60; ++i) map.add_point(Eigen::Vector3d(0.01 * i, 0, 2), 0, i);
  map.update_connections(0);
  for (size_t k = 1; k < 30; ++k) {
    Keyframe kf = keyframe_with(60, k);
    const int count = std::uniform_int_distribution<int>(5, 60)(rng);
    for (int i = 0; i < count; ++i) kf.point_ids[size_t(i)] = i;
    const int id = map.add_keyframe(std::move(kf));
    map.update_connections(id);
    if (k % 7 == 0) {  // some points lose their first views
      for (int i = 0; i < 10; ++i) map.erase_observation(i, int(k) - 3);
      map.update_connections(int(k) - 3);
    }
  }
  for (const Keyframe& k : map.keyframes()) {
    std::vector<std::pair<int, int>> ranked;
    for (const auto& [other, weight] : k.shared_points) ranked.push_back({-weight, other});
    std::sort(ranked.begin(), ranked.end());
    std::vector<int> expected;
    for (const auto& [negative, other] : ranked)
      if (-negative >= 15) expected.push_back(other);
    if (expected.empty() && !ranked.empty()) expected.push_back(ranked.front().second);
    EXPECT_EQ(k.covisible, expected) << "keyframe " << k.frame_index;
  }
}

TEST(Map, SpanningTreeParentIsTheBestNeighbourAtInsertion) {
  const Map map = map_sharing({20, 10, 16});
  EXPECT_EQ(map.keyframe(0).parent, -1);
  EXPECT_EQ(map.keyframe(1).parent, 0);
  EXPECT_EQ(map.keyframe(3).parent, 0);  // 0 and 1 both share 16: the lower index
  EXPECT_EQ(map.keyframe(0).children, (std::vector<int>{1, 2, 3}));
}

TEST(Map, CullingAKeyframeReparentsItsChildrenAndKeepsItsRelativePose) {
  // Keyframe 0 makes points 0..39 and keyframe 1 (seeing them all) points 40..79; keyframe 2
  // sees 20..79 (20 shared with 0, 60 with 1) and keyframe 3 30..79 (10 with 0, 50 with 1 and
  // 2): both hang from 1 in the spanning tree.
  struct Range {
    int begin, end;
  };
  const Range tracked[] = {{0, 0}, {0, 40}, {20, 80}, {30, 80}};  // keypoint i sees point i
  const Range made[] = {{0, 40}, {40, 80}, {0, 0}, {0, 0}};
  Map map(PyramidGeometry{}, 15);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int k = 0; k < 4; ++k) {
    T.translation().x() = 0.1 * k;
    Keyframe kf = keyframe_with(80, size_t(k), T);
    for (int i = tracked[k].begin; i < tracked[k].end; ++i) kf.point_ids[size_t(i)] = i;
    const int id = map.add_keyframe(std::move(kf));
    for (int i = made[k].begin; i < made[k].end; ++i)
      map.add_point(Eigen::Vector3d(0.01 * i, 0, 2), id, i);
    map.update_connections(id);
  }
  ASSERT_EQ(map.keyframe(2).parent, 1);
  ASSERT_EQ(map.keyframe(3).parent, 1);
  const Eigen::Isometry3d T_0_1 = map.keyframe(0).T_c_w * map.keyframe(1).T_w_c;

  map.cull_keyframe(1);
  const Keyframe& culled = map.keyframe(1);
  EXPECT_TRUE(culled.culled);
  EXPECT_EQ(std::count_if(culled.point_ids.begin(), culled.point_ids.end(),
                          [](int id) { return id >= 0; }),
            0);
  EXPECT_EQ(map.point(0).num_observations(), 1);   // only keyframe 0 now
  EXPECT_EQ(map.point(50).reference_keyframe, 2);  // the next observer took over
  for (int k : {0, 2, 3}) {
    EXPECT_EQ(map.keyframe(k).shared_points.count(1), 0u) << k;
    EXPECT_EQ(std::count(map.keyframe(k).covisible.begin(), map.keyframe(k).covisible.end(), 1), 0)
        << k;
  }
  // Child 2 shares most with the culled keyframe's parent (20 > 10): it goes first, to 0;
  // child 3 then shares 50 with 2 against 10 with 0.
  EXPECT_EQ(map.keyframe(2).parent, 0);
  EXPECT_EQ(map.keyframe(3).parent, 2);
  EXPECT_EQ(map.keyframe(0).children, (std::vector<int>{2}));
  EXPECT_EQ(map.keyframe(2).children, (std::vector<int>{3}));
  EXPECT_EQ(culled.parent, 0);

  // The culled keyframe follows its parent at the relative pose it had.
  Eigen::Isometry3d moved = Eigen::Isometry3d::Identity();
  moved.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  moved.translation() = Eigen::Vector3d(1, 2, 3);
  map.set_keyframe_pose(0, moved);
  map.place_culled_keyframes();
  EXPECT_TRUE(map.keyframe(1).T_w_c.isApprox(moved * T_0_1, 1e-12));
  EXPECT_EQ(map.num_culled_keyframes(), 1);
}

TEST(Map, RepresentativeDescriptorHasTheLeastMedianDistance) {
  Map map(PyramidGeometry{}, 15);
  // Three views of one point: descriptors a, b, c with 0, 8 and 40 bits set. Each one's sorted
  // distances, itself included: a {0, 8, 40}, b {0, 8, 32}, c {0, 32, 40}; the medians 8, 8
  // and 32: a wins the tie by coming first.
  const int bytes_set[3] = {0, 1, 5};
  for (int k = 0; k < 3; ++k) {
    Keyframe kf = keyframe_with(1, size_t(k));
    for (int b = 0; b < bytes_set[k]; ++b) kf.descriptors.at<uchar>(0, b) = 0xFF;
    if (k > 0) kf.point_ids[0] = 0;
    map.add_keyframe(std::move(kf));
    if (k == 0) map.add_point(Eigen::Vector3d(0, 0, 2), 0, 0);
  }
  map.update_point_descriptor(0);
  EXPECT_EQ(nonzero_bytes(map.point(0).descriptor), 0);
  // Without the first view, the 1-byte descriptor is the one closest to the rest.
  map.erase_observation(0, 0);
  map.update_point_descriptor(0);
  EXPECT_EQ(nonzero_bytes(map.point(0).descriptor), 1);
}

TEST(Map, RepresentativeDescriptorMatchesABruteForceChoiceForManyViews) {
  // Random descriptors seen from 1 to 40 keyframes (beyond kDescriptorViews = 32 only the most
  // recent 32 take part). The reference sorts each view's distances to the others, itself
  // included, takes the ((n - 1) / 2)-th and keeps the first view with the least.
  std::mt19937 rng(11);
  for (size_t views : {1u, 2u, 3u, 4u, 7u, 16u, 31u, 32u, 33u, 40u}) {
    Map map(PyramidGeometry{}, 15);
    std::vector<Descriptor> seen;
    for (size_t k = 0; k < views; ++k) {
      Keyframe kf = keyframe_with(1, k);
      Descriptor d;
      // Near a common centre, so that medians differ by a few bits and ties occur.
      for (int b = 0; b < kDescriptorBytes; ++b) d[size_t(b)] = uint8_t(b * 37);
      for (int flip = 0; flip < 12; ++flip) d[rng() % 32] ^= uint8_t(1u << (rng() % 8));
      std::copy(d.begin(), d.end(), kf.descriptors.ptr<uchar>(0));
      seen.push_back(d);
      if (k > 0) kf.point_ids[0] = 0;
      map.add_keyframe(std::move(kf));
      if (k == 0) map.add_point(Eigen::Vector3d(0, 0, 2), 0, 0);
    }
    map.update_point_descriptor(0);
    const size_t first = views > Map::kDescriptorViews ? views - Map::kDescriptorViews : 0;
    size_t best = first;
    int best_median = 1 << 30;
    for (size_t i = first; i < views; ++i) {
      std::vector<int> distances;
      for (size_t j = first; j < views; ++j) {
        int bits = 0;
        for (int b = 0; b < kDescriptorBytes; ++b)
          bits += __builtin_popcount(unsigned(seen[i][size_t(b)] ^ seen[j][size_t(b)]));
        distances.push_back(bits);
      }
      std::sort(distances.begin(), distances.end());
      const int median = distances[(distances.size() - 1) / 2];
      if (median < best_median) best_median = median, best = i;
    }
    EXPECT_EQ(map.point(0).descriptor, seen[best]) << views << " views";
  }
}

TEST(Map, ViewingDirectionAndScaleValidDistanceRange) {
  Map map(PyramidGeometry{4, 1.2}, 15);
  map.add_keyframe(keyframe_with(1, 0, Eigen::Isometry3d::Identity(), /*octave=*/2));
  const int p = map.add_point(Eigen::Vector3d(0, 0, 2), 0, 0);
  Eigen::Isometry3d shifted = Eigen::Isometry3d::Identity();
  shifted.translation() = Eigen::Vector3d(2, 0, 2);  // sees the point from +x
  Keyframe second = keyframe_with(1, 1, shifted);
  second.point_ids[0] = p;
  map.add_keyframe(std::move(second));
  map.update_point_geometry(p);
  const MapPoint& point = map.point(p);
  // Mean of the unit directions (0, 0, 1) and (-1, 0, 0), not re-normalised (ORB-SLAM2).
  EXPECT_NEAR(point.normal.x(), -0.5, 1e-12);
  EXPECT_NEAR(point.normal.z(), 0.5, 1e-12);
  // From the reference keyframe: 2 m at octave 2, so max = 2 * 1.2^2, min = max / 1.2^3.
  EXPECT_NEAR(point.max_distance, 2 * 1.44, 1e-12);
  EXPECT_NEAR(point.min_distance, 2 * 1.44 / 1.728, 1e-12);
  EXPECT_EQ(map.predict_octave(point, 2.01), 2);
  EXPECT_EQ(map.predict_octave(point, 2 * 1.44), 0);
  EXPECT_EQ(map.predict_octave(point, 0.5), 3);  // clamped to the last level
}

TEST(Map, ReplacingAPointMovesItsObservationsToTheSurvivor) {
  Map map = map_sharing({20});
  // Keyframe 1's keypoint 30 makes its own point for keyframe 0's point 30: a duplicate.
  const int duplicate = map.add_point(Eigen::Vector3d(0.3, 0, 2), 1, 30);
  map.replace_point(duplicate, 30);
  EXPECT_TRUE(map.point(duplicate).bad);
  EXPECT_EQ(map.keyframe(1).point_ids[30], 30);
  EXPECT_EQ(map.point(30).num_observations(), 2);
  // Replacing a point by one the same keyframe already sees drops the duplicate link only.
  const int twin = map.add_point(Eigen::Vector3d(0.3, 0, 2), 1, 39);
  map.replace_point(twin, 30);
  EXPECT_EQ(map.keyframe(1).point_ids[39], -1);
  EXPECT_EQ(map.point(30).num_observations(), 2);
}

TEST(Map, CullingAPointUnlinksEveryKeypoint) {
  Map map = map_sharing({20});
  map.cull_point(5);
  EXPECT_TRUE(map.point(5).bad);
  EXPECT_EQ(map.keyframe(0).point_ids[5], -1);
  EXPECT_EQ(map.keyframe(1).point_ids[5], -1);
  map.update_connections(1);
  EXPECT_EQ(map.keyframe(1).shared_points.at(0), 19);
}

TEST(Map, ACulledPointStaysBadThroughLateUpdatesAndCopiesAreDeep) {
  Map map = map_sharing({20});
  const Eigen::Vector3d before = map.point(6).p_w;
  map.cull_point(5);
  // A BA result or a tracking count may still name the culled point: nothing happens.
  map.set_point_position(5, Eigen::Vector3d(1, 2, 3));
  map.count_found(5);
  map.erase_observation(5, 0);
  map.cull_point(5);
  EXPECT_TRUE(map.point(5).bad);
  EXPECT_TRUE(map.point(5).observations.empty());
  EXPECT_EQ(map.num_point_ids(), 40);
  EXPECT_EQ(map.num_good_points(), 39);
  // Adding an observation to it is a programming error, reported as such.
  EXPECT_THROW(map.add_observation(5, 0, 5), std::logic_error);

  Map copy = map;
  copy.set_point_position(6, Eigen::Vector3d(1, 2, 3));
  copy.cull_point(7);
  EXPECT_EQ(map.point(6).p_w, before);
  EXPECT_FALSE(map.point(7).bad);
  EXPECT_TRUE(copy.point(5).bad);
  EXPECT_EQ(copy.point(6).p_w, Eigen::Vector3d(1, 2, 3));
}

}  // namespace
}  // namespace slamkit
