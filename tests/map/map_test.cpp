#include "map/map.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

// A keyframe of `n` keypoints at pixel (100 + i, 200) with depth 2 m, observing the given
// existing points (-1: none, so a new point is made from depth).
Keyframe keyframe_observing(const std::vector<int>& point_ids, size_t frame_index) {
  Keyframe k;
  k.frame_index = frame_index;
  for (size_t i = 0; i < point_ids.size(); ++i) {
    k.keypoints.emplace_back(cv::Point2f(100.0f + float(i), 200.0f), 31.0f);
    k.undistorted.emplace_back(100.0 + double(i), 200.0);
    k.depths.push_back(2.0f);
  }
  k.descriptors = cv::Mat(int(point_ids.size()), 32, CV_8U, cv::Scalar(0));
  k.point_ids = point_ids;
  return k;
}

TEST(Map, KeyframesMakePointsFromDepthAndCountObservations) {
  const Camera camera = Camera::freiburg3();
  Map map;
  map.insert_keyframe(keyframe_observing({-1, -1, -1}, 0), camera);  // points 0, 1, 2
  map.insert_keyframe(keyframe_observing({2, -1}, 1), camera);       // sees 2, makes 3
  ASSERT_EQ(map.points().size(), 4u);
  EXPECT_EQ(map.keyframes()[1].point_ids, (std::vector<int>{2, 3}));
  EXPECT_EQ(map.point(2).observations, map.point(0).observations + 1);
  EXPECT_NEAR(map.point(0).p_w.z(), 2.0, 1e-12);  // identity pose: camera frame = world
}

TEST(Map, LocalPointsAreThoseOfTheLastKeyframesEachOnceAscending) {
  const Camera camera = Camera::freiburg3();
  Map map;
  map.insert_keyframe(keyframe_observing({-1, -1, -1, -1}, 0), camera);  // 0..3
  map.insert_keyframe(keyframe_observing({3, -1, 1}, 1), camera);        // 3, new 4, 1
  map.insert_keyframe(keyframe_observing({4, -1, 3, -1}, 2), camera);    // 4, 5, 3, 6
  EXPECT_EQ(map.local_point_ids(1), (std::vector<int>{3, 4, 5, 6}));
  EXPECT_EQ(map.local_point_ids(2), (std::vector<int>{1, 3, 4, 5, 6}));
  EXPECT_EQ(map.local_point_ids(10), (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_TRUE(Map().local_point_ids(3).empty());
}

}  // namespace
}  // namespace slamkit
