#include "mapping/local_mapper.h"

#include <gtest/gtest.h>

#include <random>

#include "core/pose.h"

namespace slamkit {
namespace {

// A world of points on a plane 2 m in front of the first camera, each with its own random
// descriptor; keyframes see them through an exact pinhole camera.
struct World {
  Camera camera = Camera::freiburg3();
  std::vector<Eigen::Vector3d> points;
  cv::Mat descriptors;

  explicit World(int n) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> x(-0.8, 0.8), y(-0.6, 0.6);
    descriptors.create(n, 32, CV_8U);
    cv::randu(descriptors, 0, 256);
    for (int i = 0; i < n; ++i) points.emplace_back(x(rng), y(rng), 2.0);
  }

  // Keypoint i of the keyframe observes world point i when it projects into the image.
  Keyframe view(const Eigen::Isometry3d& T_w_c, size_t frame_index) const {
    Keyframe k;
    k.frame_index = frame_index;
    k.T_w_c = T_w_c;
    const Eigen::Isometry3d T_c_w = T_w_c.inverse();
    for (size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d p_c = T_c_w * points[i];
      const Eigen::Vector2d uv = camera.project(p_c);
      k.keypoints.emplace_back(cv::Point2f(float(uv.x()), float(uv.y())), 31.0f);
      k.undistorted.push_back(uv);
      k.depths.push_back(camera.contains(uv) ? float(p_c.z()) : 0.0f);
    }
    k.descriptors = descriptors.clone();
    k.point_ids.assign(points.size(), -1);
    return k;
  }
};

Settings without_ba() {
  Settings s;
  s.optimization.local_ba.enabled = false;
  return s;
}

Eigen::Isometry3d moved(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

TEST(LocalMapper, KeypointsWithDepthMakePointsAtTheirBackProjection) {
  const World world(50);
  Map map;
  LocalMapper mapper(world.camera, without_ba(), map, false);
  mapper.insert_keyframe(world.view(moved(0.1), 0), 1.0);
  const MappingReport& report = mapper.reports().back();
  EXPECT_EQ(report.new_points, int(world.points.size()));
  for (size_t i = 0; i < world.points.size(); ++i)
    EXPECT_LT((map.point(map.keyframe(0).point_ids[i]).p_w - world.points[i]).norm(), 1e-9);
}

TEST(LocalMapper, TrackedPointsGainObservationsAndLinkTheKeyframes) {
  const World world(50);
  Map map;
  LocalMapper mapper(world.camera, without_ba(), map, false);
  mapper.insert_keyframe(world.view(Eigen::Isometry3d::Identity(), 0), 1.0);
  Keyframe second = world.view(moved(0.05), 1);
  second.point_ids = map.keyframe(0).point_ids;  // tracking matched every point
  mapper.insert_keyframe(std::move(second), 1.0);
  const MappingReport& report = mapper.reports().back();
  EXPECT_EQ(report.new_points, 0);
  EXPECT_EQ(map.point(0).num_observations(), 2);
  EXPECT_EQ(map.keyframe(1).shared_points.at(0), 50);
  EXPECT_EQ(map.keyframe(1).parent, 0);
}

TEST(LocalMapper, DuplicatesOfTheSamePointAreFused) {
  const World world(60);
  Map map;
  LocalMapper mapper(world.camera, without_ba(), map, false);
  mapper.insert_keyframe(world.view(Eigen::Isometry3d::Identity(), 0), 1.0);
  // Tracking matched only the first 30 points: the second keyframe links those and makes
  // fresh points for the other 30, which are duplicates of keyframe 0's.
  Keyframe second = world.view(moved(0.05), 1);
  for (size_t i = 0; i < 30; ++i) second.point_ids[i] = map.keyframe(0).point_ids[i];
  mapper.insert_keyframe(std::move(second), 1.0);
  const MappingReport& report = mapper.reports().back();
  EXPECT_EQ(report.new_points, 30);
  EXPECT_EQ(report.fused_points, 30);
  EXPECT_EQ(map.num_good_points(), 60);
  for (size_t i = 0; i < 60; ++i)
    EXPECT_EQ(map.keyframe(1).point_ids[i], map.keyframe(0).point_ids[i]);
}

TEST(LocalMapper, PointsSeenByOneKeyframeAreCulledAfterTwoMore) {
  const World world(40);
  Settings settings = without_ba();
  settings.mapping.fuse_duplicates = false;
  Map map;
  LocalMapper mapper(world.camera, settings, map, false);
  mapper.insert_keyframe(world.view(Eigen::Isometry3d::Identity(), 0), 1.0);
  // Later keyframes track only the first 20 points; their own new points are elsewhere.
  for (size_t k = 1; k <= 2; ++k) {
    Keyframe next = world.view(moved(0.02 * double(k)), k);
    for (size_t i = 0; i < next.depths.size(); ++i)
      next.point_ids[i] = i < 20 ? map.keyframe(0).point_ids[i] : -1;
    for (size_t i = 20; i < next.depths.size(); ++i) next.depths[i] = 0;  // no new points
    mapper.insert_keyframe(std::move(next), 1.0);
    const MappingReport& report = mapper.reports().back();
    EXPECT_EQ(report.culled_points, k == 2 ? 20 : 0) << "keyframe " << k;
  }
  EXPECT_EQ(map.num_good_points(), 20);
}

// Five keyframes a little apart, each after the first tracking every point of the first; local
// BA on but skipped as quasi-static (culling comes with the back end, not its solves), and
// culling on.
std::vector<int> culled_after_five_views(int observers, int later_octave) {
  const World world(60);
  Settings settings;
  settings.optimization.local_ba.min_motion = 1e9;
  settings.mapping.cull_keyframes = true;
  settings.mapping.culling_observers = observers;
  Map map;
  LocalMapper mapper(world.camera, settings, map, false);
  mapper.insert_keyframe(world.view(Eigen::Isometry3d::Identity(), 0), 0);
  for (size_t k = 1; k < 5; ++k) {
    Keyframe next = world.view(moved(0.01 * double(k)), k);
    next.point_ids = map.keyframe(0).point_ids;
    if (k > 1)
      for (cv::KeyPoint& kp : next.keypoints) kp.octave = later_octave;
    mapper.insert_keyframe(std::move(next), 0);
  }
  mapper.finish();
  std::vector<int> culled;
  for (size_t k = 0; k < map.keyframes().size(); ++k)
    if (map.keyframe(int(k)).culled) culled.push_back(int(k));
  return culled;
}

TEST(LocalMapper, KeyframesWhosePointsThreeOthersSeeAreCulled) {
  // Each insertion checks the previous keyframe's neighbours. When keyframe 4 comes, keyframe
  // 1's points are each seen by 0, 2 and 3: culled. At the end keyframe 2's are seen by 0, 3
  // and 4: culled; keyframe 3's then only by 0 and 4. Keyframe 0 holds the world frame.
  EXPECT_EQ(culled_after_five_views(3, 0), (std::vector<int>{1, 2}));
  // Four other views: only keyframe 1 at the end (0, 2, 3 and 4 see its points).
  EXPECT_EQ(culled_after_five_views(4, 0), (std::vector<int>{1}));
  EXPECT_EQ(culled_after_five_views(5, 0), (std::vector<int>{}));
  // Views at an octave more than one coarser than the keyframe's own do not count
  // (ORB-SLAM2): keyframe 1 (octave 0) stays, seen at octave 2 by 2, 3 and 4, while those are
  // seen finely enough by 0, 1 and each other.
  EXPECT_EQ(culled_after_five_views(3, 2), (std::vector<int>{2, 3}));
  EXPECT_EQ(culled_after_five_views(3, 1), (std::vector<int>{1, 2}));
}

TEST(LocalMapper, QuasiStaticMotionIsThePapersWeightedSum) {
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.translation() = Eigen::Vector3d(0.01, 0, 0);
  step.linear() = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const std::vector<Eigen::Isometry3d> poses = {Eigen::Isometry3d::Identity(), step, step * step};
  // Two equal steps: 2 * (0.01^2 + 15 * 0.01^2).
  EXPECT_NEAR(quasi_static_motion(poses, 15), 2 * 16 * 1e-4, 1e-12);
  EXPECT_EQ(quasi_static_motion({step}, 15), 0);
}

}  // namespace
}  // namespace slamkit
