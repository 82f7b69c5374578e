#include "optimization/map_pose_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace slamkit {
namespace {

constexpr int kKeyframes = 24;
constexpr int kPointsEach = 120;  // each also seen by the next keyframe: covisibility 120

Eigen::Isometry3d pose(double yaw, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = t;
  return T;
}

struct DriftedMap {
  std::vector<Eigen::Isometry3d> truth;  // keyframe poses
  std::vector<Eigen::Vector3d> true_points;
  Map map;
};

// Keyframes once round a 2 m circle whose tracked poses drift (each step's yaw off by 0.01 rad),
// each creating points in front of it where tracking put them (true in its own frame, so
// drifted in the world), each point seen again by the next keyframe.
DriftedMap drifted_map() {
  DriftedMap d;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> lateral(-0.8, 0.8), ahead(0.8, 2.5);
  Eigen::Isometry3d tracked = Eigen::Isometry3d::Identity();
  for (int k = 0; k < kKeyframes; ++k) {
    const double a = 2 * M_PI * k / kKeyframes;
    d.truth.push_back(pose(-a, Eigen::Vector3d(std::sin(a), 0, std::cos(a))));
    if (k == 0) tracked = d.truth[0];
    else tracked = tracked * (d.truth[size_t(k - 1)].inverse() * d.truth[size_t(k)]) *
                   pose(0.01, Eigen::Vector3d::Zero());
    Keyframe keyframe;
    keyframe.set_pose(tracked);
    const int keypoints = k == 0 ? kPointsEach : 2 * kPointsEach;
    keyframe.keypoints.resize(size_t(keypoints));
    keyframe.undistorted.assign(size_t(keypoints), Eigen::Vector2d::Zero());
    keyframe.depths.assign(size_t(keypoints), 1.0f);
    keyframe.descriptors = cv::Mat::zeros(keypoints, 32, CV_8U);
    keyframe.point_ids.assign(size_t(keypoints), -1);
    const int id = d.map.add_keyframe(keyframe);
    for (int j = 0; j < kPointsEach; ++j) {
      const Eigen::Vector3d p_c(lateral(rng), lateral(rng), ahead(rng));
      d.true_points.push_back(d.truth[size_t(k)] * p_c);
      d.map.add_point(tracked * p_c, id, j);
    }
    if (k > 0)  // the previous keyframe's points, seen again
      for (int j = 0; j < kPointsEach; ++j)
        d.map.add_observation((k - 1) * kPointsEach + j, id, kPointsEach + j);
    d.map.update_connections(id);
  }
  return d;
}

double mean_point_error(const DriftedMap& d) {
  double sum = 0;
  for (size_t i = 0; i < d.true_points.size(); ++i)
    sum += (d.map.point(int(i)).p_w - d.true_points[i]).norm();
  return sum / double(d.true_points.size());
}

TEST(MapPoseGraph, EssentialGraphHasTreeCovisibilityAndLoopEdges) {
  const DriftedMap d = drifted_map();
  const LoopConstraint loop{kKeyframes - 1, 0, d.truth.back().inverse() * d.truth[0]};
  const PoseGraph graph = essential_graph(d.map, {loop}, {});
  // A chain: each keyframe's parent is the one before (no other pair shares 100 points).
  EXPECT_EQ(graph.edges.size(), size_t(kKeyframes));
  EXPECT_EQ(graph.edges.back().from, kKeyframes - 1);
  EXPECT_TRUE(graph.fixed[0]);
  EXPECT_FALSE(graph.fixed[1]);
}

TEST(MapPoseGraph, LoopCorrectionMovesKeyframesAndTheirPoints) {
  DriftedMap d = drifted_map();
  const double end_before = (d.map.keyframes().back().centre() - d.truth.back().translation()).norm();
  const double points_before = mean_point_error(d);
  ASSERT_GT(end_before, 0.2);
  const LoopConstraint loop{kKeyframes - 1, 0, d.truth.back().inverse() * d.truth[0]};
  ASSERT_TRUE(correct_loops(d.map, {loop}, {}).solved);
  const double end_after = (d.map.keyframes().back().centre() - d.truth.back().translation()).norm();
  const double points_after = mean_point_error(d);
  std::printf("loop correction: last keyframe %.3f -> %.3f m, points %.3f -> %.3f m\n",
              end_before, end_after, points_before, points_after);
  EXPECT_LT(end_after, 0.1 * end_before);
  EXPECT_LT(points_after, 0.2 * points_before);
  // A point stays where its keyframe sees it.
  const MapPoint& p = d.map.point(5 * kPointsEach + 7);
  const Keyframe& reference = d.map.keyframe(p.reference_keyframe);
  EXPECT_LT((reference.T_c_w * p.p_w - d.truth[5].inverse() * d.true_points[5 * kPointsEach + 7])
                .norm(),
            1e-9);
}

}  // namespace
}  // namespace slamkit
