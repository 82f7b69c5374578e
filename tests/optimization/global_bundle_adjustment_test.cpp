#include <gtest/gtest.h>

#include <cstdio>

#include "optimization/ba_test_scene.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {
namespace {

// 12 cameras, 600 points, only the first pose fixed (depth fixes the scale).
TestScene first_fixed_scene(double pixel_noise) {
  TestSceneOptions options;
  options.num_poses = 12;
  options.num_points = 600;
  options.pixel_noise = pixel_noise;
  TestScene scene = make_test_scene(options);
  scene.truth.pose_fixed[0] = true;
  return scene;
}

BaProblem start_of(const TestScene& scene) {
  return perturbed(scene.truth, 0.03, 1.5 * M_PI / 180, 0.02);
}

TEST(GlobalBundleAdjustment, RecoversExactAnswerWithFirstPoseFixed) {
  const TestScene scene = first_fixed_scene(0);
  for (const bool robust : {true, false}) {
    SCOPED_TRACE(robust);
    BaProblem problem = start_of(scene);
    const Eigen::Isometry3d first = problem.T_c_w[0];
    GlobalBaSettings settings;
    settings.robust = robust;
    const BaReport report =
        global_bundle_adjustment(problem, scene.intrinsics, scene.residual, settings);
    ASSERT_TRUE(report.solved);
    EXPECT_EQ(report.num_outliers, 0);
    const PoseErrors errors = max_pose_errors(problem, scene.truth);
    EXPECT_LT(errors.metres, 1e-3);
    EXPECT_LT(errors.degrees, 0.01);
    EXPECT_LT(max_point_error(problem, scene.truth), 1e-3);
    EXPECT_TRUE(bit_identical(problem.T_c_w[0], first));
  }
}

TEST(GlobalBundleAdjustment, RobustModeRejectsGrossOutliers) {
  const TestScene scene = first_fixed_scene(0);
  // Points free throughout (ORB-SLAM2) and held after two iterations (paper, the default).
  for (const int fix_after : {-1, 2}) {
    SCOPED_TRACE(fix_after);
    BaProblem problem = start_of(scene);
    std::vector<int> moved;
    for (size_t i = 7; i < problem.observations.size() && moved.size() < 20; i += 70) {
      problem.observations[i].uv += Eigen::Vector2d(-40, 30);
      moved.push_back(static_cast<int>(i));
    }
    GlobalBaSettings settings;
    settings.fix_points_after_iterations = fix_after;
    const BaReport report =
        global_bundle_adjustment(problem, scene.intrinsics, scene.residual, settings);
    ASSERT_TRUE(report.solved);
    EXPECT_LE(report.iterations, settings.iterations + settings.refine_iterations);
    EXPECT_GE(report.iterations, 2);
    for (int i : moved) EXPECT_TRUE(report.outlier[i]) << i;
    // A point seen twice cannot tell which view is wrong: a few partners may go too.
    EXPECT_LE(report.num_outliers, static_cast<int>(moved.size()) + 5);
    if (fix_after >= 0) continue;  // the held points keep what two robust iterations left
    // No bias: the exact answer again, for the poses and every point still measured twice.
    const PoseErrors errors = max_pose_errors(problem, scene.truth);
    EXPECT_LT(errors.metres, 1e-3);
    EXPECT_LT(errors.degrees, 0.01);
    std::vector<int> inliers(problem.p_w.size());
    for (size_t i = 0; i < problem.observations.size(); ++i) {
      inliers[problem.observations[i].point] += !report.outlier[i];
    }
    for (size_t j = 0; j < problem.p_w.size(); ++j) {
      if (inliers[j] >= 2) {
        EXPECT_LT((problem.p_w[j] - scene.truth.p_w[j]).norm(), 1e-3) << j;
      }
    }
  }
}

TEST(GlobalBundleAdjustment, PointsHeldFixedAfterGivenIterations) {
  const TestScene scene = first_fixed_scene(0.5);
  const BaProblem start = start_of(scene);
  GlobalBaSettings settings;
  settings.fix_points_after_iterations = 2;
  BaProblem after_two = start;
  const BaReport report =
      global_bundle_adjustment(after_two, scene.intrinsics, scene.residual, settings);
  ASSERT_TRUE(report.solved);
  EXPECT_GE(report.iterations, 3);  // the poses went on after the points stopped

  // The points are exactly those of a run that stops after two iterations.
  GlobalBaSettings two_iterations;
  two_iterations.iterations = 2;
  two_iterations.refine_iterations = 0;
  two_iterations.fix_points_after_iterations = -1;
  BaProblem stopped = start;
  global_bundle_adjustment(stopped, scene.intrinsics, scene.residual, two_iterations);
  EXPECT_TRUE(bit_identical_points(after_two, stopped));
  // But not the poses, which went on alone: with the points equal, the problems can differ only
  // there (after two iterations the poses are already as close to the truth as half a pixel
  // allows).
  EXPECT_FALSE(bit_identical(after_two, stopped));
  EXPECT_LT(max_pose_errors(after_two, scene.truth).metres, 0.02);
}

TEST(GlobalBundleAdjustment, RecoversAnswerUnderPixelNoise) {
  const TestScene scene = first_fixed_scene(0.5);
  BaProblem problem = start_of(scene);
  const BaReport report =
      global_bundle_adjustment(problem, scene.intrinsics, scene.residual, GlobalBaSettings());
  ASSERT_TRUE(report.solved);
  // Half a pixel along a chain of 12 cameras held only by the first: millimetres and a tenth
  // of a degree at the far end.
  const PoseErrors errors = max_pose_errors(problem, scene.truth);
  EXPECT_LT(errors.metres, 0.02);
  EXPECT_LT(errors.degrees, 0.2);
}

TEST(GlobalBundleAdjustment, RunsAreBitIdentical) {
  const TestScene scene = first_fixed_scene(0.5);
  BaProblem first = start_of(scene), second = first;
  const GlobalBaSettings settings;
  global_bundle_adjustment(first, scene.intrinsics, scene.residual, settings);
  global_bundle_adjustment(second, scene.intrinsics, scene.residual, settings);
  for (size_t i = 0; i < first.T_c_w.size(); ++i)
    EXPECT_TRUE(bit_identical(first.T_c_w[i], second.T_c_w[i])) << i;
  EXPECT_TRUE(bit_identical_points(first, second));
}

TEST(GlobalBundleAdjustment, NoFreePoseOrNoObservationsIsNotSolved) {
  const TestScene scene = first_fixed_scene(0);
  BaProblem problem = start_of(scene);
  problem.pose_fixed.assign(problem.T_c_w.size(), true);
  EXPECT_FALSE(
      global_bundle_adjustment(problem, scene.intrinsics, scene.residual, GlobalBaSettings())
          .solved);
  problem = start_of(scene);
  problem.observations.clear();
  EXPECT_FALSE(
      global_bundle_adjustment(problem, scene.intrinsics, scene.residual, GlobalBaSettings())
          .solved);
}

TEST(GlobalBundleAdjustment, TimingOnWholeSequence) {
  // A long sequence: 150 keyframes, 30,000 points, 150,000 observations.
  TestSceneOptions options;
  options.num_poses = 150;
  options.num_points = 30000;
  options.views_per_point = 5;
  options.pixel_noise = 0.5;
  TestScene scene = make_test_scene(options);
  scene.truth.pose_fixed[0] = true;
  BaProblem problem = start_of(scene);
  const double cpu = thread_cpu_seconds();
  const BaReport report =
      global_bundle_adjustment(problem, scene.intrinsics, scene.residual, GlobalBaSettings());
  const double cpu_seconds = thread_cpu_seconds() - cpu;
  ASSERT_TRUE(report.solved);
  std::printf(
      "global BA, %zu poses, %zu points, %zu observations: %.2f s (%.2f s CPU), %d iterations, "
      "%d outliers, max pose error %.2f mm\n",
      problem.T_c_w.size(), problem.p_w.size(), problem.observations.size(), report.seconds,
      cpu_seconds, report.iterations, report.num_outliers,
      max_pose_errors(problem, scene.truth).metres * 1e3);
}

}  // namespace
}  // namespace slamkit
