#include "optimization/pose_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace slamkit {
namespace {

constexpr int kNodes = 24;

Eigen::Isometry3d pose(double yaw, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T.translation() = t;
  return T;
}

// A camera walking once round a 2 m circle, looking ahead, back to where it started.
std::vector<Eigen::Isometry3d> circle() {
  std::vector<Eigen::Isometry3d> T_w_c;
  for (int i = 0; i < kNodes; ++i) {
    const double a = 2 * M_PI * i / kNodes;
    T_w_c.push_back(pose(-a, Eigen::Vector3d(std::sin(a), 0.1 * std::sin(3 * a), std::cos(a))));
  }
  return T_w_c;
}

double translation_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

// Odometry edges from `truth`, each step's yaw off by `drift` radians, accumulated into the
// start poses (a tracker's drift); plus the loop edge last -> first, exact.
PoseGraph drifted_graph(const std::vector<Eigen::Isometry3d>& truth, double drift) {
  PoseGraph graph;
  graph.fixed.assign(kNodes, false);
  graph.fixed[0] = true;
  graph.T_w_c.push_back(truth[0]);
  for (int i = 1; i < kNodes; ++i) {
    const Eigen::Isometry3d step = truth[size_t(i - 1)].inverse() * truth[size_t(i)];
    const Eigen::Isometry3d measured = step * pose(drift, Eigen::Vector3d::Zero());
    graph.edges.push_back({i - 1, i, measured, 1});
    graph.T_w_c.push_back(graph.T_w_c.back() * measured);
  }
  graph.edges.push_back({kNodes - 1, 0, truth[kNodes - 1].inverse() * truth[0], 1});
  return graph;
}

TEST(PoseGraph, ExactEdgesRecoverTheTruthFromADriftedStart) {
  const std::vector<Eigen::Isometry3d> truth = circle();
  PoseGraph graph = drifted_graph(truth, 0.01);
  for (size_t i = 1; i < size_t(kNodes); ++i)  // the odometry, now exact
    graph.edges[i - 1].T_from_to = truth[i - 1].inverse() * truth[i];
  const PoseGraphReport report = optimise_pose_graph(graph, 50);
  ASSERT_TRUE(report.solved);
  EXPECT_LT(report.final_cost, 1e-16);
  for (int i = 0; i < kNodes; ++i) {
    EXPECT_LT(translation_error(graph.T_w_c[size_t(i)], truth[size_t(i)]), 1e-8) << i;
    EXPECT_TRUE(graph.T_w_c[size_t(i)].linear().isApprox(truth[size_t(i)].linear(), 1e-8)) << i;
  }
}

TEST(PoseGraph, LoopEdgeRemovesMostOfAnInjectedDrift) {
  const std::vector<Eigen::Isometry3d> truth = circle();
  PoseGraph graph = drifted_graph(truth, 0.01);  // 0.57 deg a step, 13 deg round the loop
  double worst_before = 0;
  for (int i = 0; i < kNodes; ++i)
    worst_before = std::max(worst_before, translation_error(graph.T_w_c[size_t(i)], truth[size_t(i)]));
  const double end_before = translation_error(graph.T_w_c.back(), truth.back());
  ASSERT_GT(end_before, 0.2);  // the drift is real: decimetres at the loop's end

  ASSERT_TRUE(optimise_pose_graph(graph, 50).solved);
  double worst_after = 0;
  for (int i = 0; i < kNodes; ++i)
    worst_after = std::max(worst_after, translation_error(graph.T_w_c[size_t(i)], truth[size_t(i)]));
  const double end_after = translation_error(graph.T_w_c.back(), truth.back());
  std::printf("pose graph: loop end %.3f -> %.3f m, worst node %.3f -> %.3f m\n", end_before,
              end_after, worst_before, worst_after);
  EXPECT_LT(end_after, 0.1 * end_before);
  EXPECT_LT(worst_after, 0.5 * worst_before);
  EXPECT_EQ(graph.T_w_c[0].matrix(), truth[0].matrix());  // the fixed node did not move
}

TEST(PoseGraph, RunsAreBitIdentical) {
  const std::vector<Eigen::Isometry3d> truth = circle();
  PoseGraph a = drifted_graph(truth, 0.01), b = drifted_graph(truth, 0.01);
  optimise_pose_graph(a, 20);
  optimise_pose_graph(b, 20);
  for (int i = 0; i < kNodes; ++i)
    EXPECT_EQ(std::memcmp(a.T_w_c[size_t(i)].matrix().data(), b.T_w_c[size_t(i)].matrix().data(),
                          16 * sizeof(double)),
              0);
}

TEST(PoseGraph, NothingFreeIsNotSolvedAndBadEdgesThrow) {
  PoseGraph graph = drifted_graph(circle(), 0.01);
  PoseGraph all_fixed = graph;
  all_fixed.fixed.assign(kNodes, true);
  EXPECT_FALSE(optimise_pose_graph(all_fixed, 10).solved);
  PoseGraph bad = graph;
  bad.edges.push_back({0, kNodes, Eigen::Isometry3d::Identity(), 1});
  EXPECT_THROW(optimise_pose_graph(bad, 10), std::invalid_argument);
}

}  // namespace
}  // namespace slamkit
