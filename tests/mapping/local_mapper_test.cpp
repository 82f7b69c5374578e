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
  s.optimization.local.enabled = false;
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
