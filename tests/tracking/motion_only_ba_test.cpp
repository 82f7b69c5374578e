#include "tracking/motion_only_ba.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/pose.h"

namespace slamkit {
namespace {

constexpr double kDeg = M_PI / 180;

Eigen::Isometry3d pose(const Eigen::Vector3d& axis, double angle_deg, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(angle_deg * kDeg, axis.normalized()).matrix();
  T.translation() = t;
  return T;
}

struct Matches {
  std::vector<PointObservation> observations;
  std::vector<bool> is_outlier;
};

// Points 0.8-4 m in front of the camera, seen with 1 px noise and Kinect-like depth noise
// (1.4 mm z^2); an outlier's pixel is 15-60 px off.
Matches make_matches(const Camera& cam, const Eigen::Isometry3d& T_w_c, int n, double outlier_ratio,
                     uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(10, cam.width - 10), v(10, cam.height - 10);
  std::uniform_real_distribution<double> z(0.8, 4.0), unit(0, 1), off(15, 60), angle(0, 2 * M_PI);
  std::normal_distribution<double> gauss(0, 1);
  Matches m;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d uv(u(rng), v(rng));
    const double depth = z(rng);
    PointObservation o;
    o.p_w = T_w_c * cam.back_project(uv, depth);
    o.uv = uv + Eigen::Vector2d(gauss(rng), gauss(rng));
    o.depth = depth + 0.0014 * depth * depth * gauss(rng);
    const bool outlier = unit(rng) < outlier_ratio;
    if (outlier) {
      const double a = angle(rng);
      o.uv += off(rng) * Eigen::Vector2d(std::cos(a), std::sin(a));
    }
    m.observations.push_back(o);
    m.is_outlier.push_back(outlier);
  }
  return m;
}

struct Outcome {
  double translation_error, rotation_error_deg;
  int flagged_outliers, true_outliers, kept_inliers, true_inliers;
};

Outcome judge(const PoseRefinement& r, const Matches& m, const Eigen::Isometry3d& truth) {
  Outcome o{};
  o.translation_error = (r.T_w_c.translation() - truth.translation()).norm();
  o.rotation_error_deg = rotation_angle(r.T_w_c.inverse() * truth) / kDeg;
  for (size_t i = 0; i < m.is_outlier.size(); ++i) {
    if (m.is_outlier[i]) {
      ++o.true_outliers;
      o.flagged_outliers += !r.inliers[i];
    } else {
      ++o.true_inliers;
      o.kept_inliers += r.inliers[i];
    }
  }
  return o;
}

const Eigen::Isometry3d kTruth = pose({0.3, 1, -0.2}, 40, {1.0, -0.4, 2.0});

TEST(MotionOnlyBa, RecoversPoseAndFlagsOutliers) {
  const Camera cam = Camera::freiburg3();
  const Matches m = make_matches(cam, kTruth, 300, 0.2, 1);
  const Eigen::Isometry3d guess = kTruth * pose({1, -1, 0.5}, 3, {0.05, -0.04, 0.03});
  const PoseRefinement r = motion_only_ba(m.observations, cam, guess, MotionBaSettings{});
  ASSERT_TRUE(r.ok);
  const Outcome o = judge(r, m, kTruth);
  EXPECT_LT(o.translation_error, 0.002);
  EXPECT_LT(o.rotation_error_deg, 0.05);
  EXPECT_EQ(o.flagged_outliers, o.true_outliers);
  EXPECT_GT(o.kept_inliers, 0.9 * o.true_inliers);  // the chi2 test drops ~5% of true ones
  EXPECT_EQ(r.num_inliers, o.kept_inliers + o.true_outliers - o.flagged_outliers);
}

TEST(MotionOnlyBa, WorksWithoutDepth) {
  const Camera cam = Camera::freiburg3();
  const Matches m = make_matches(cam, kTruth, 300, 0.2, 2);
  MotionBaSettings settings;
  settings.use_depth = false;
  const Eigen::Isometry3d guess = kTruth * pose({0, 1, 0.5}, 2, {0.03, 0.02, -0.03});
  const PoseRefinement r = motion_only_ba(m.observations, cam, guess, settings);
  ASSERT_TRUE(r.ok);
  const Outcome o = judge(r, m, kTruth);
  EXPECT_LT(o.translation_error, 0.01);
  EXPECT_LT(o.rotation_error_deg, 0.1);
  EXPECT_EQ(o.flagged_outliers, o.true_outliers);
}

TEST(MotionOnlyBa, DepthMakesTranslationMoreAccurate) {
  const Camera cam = Camera::freiburg3();
  double error_with = 0, error_without = 0;
  for (uint32_t seed = 10; seed < 15; ++seed) {
    const Matches m = make_matches(cam, kTruth, 100, 0, seed);
    MotionBaSettings settings;
    error_with +=
        judge(motion_only_ba(m.observations, cam, kTruth, settings), m, kTruth).translation_error;
    settings.use_depth = false;
    error_without +=
        judge(motion_only_ba(m.observations, cam, kTruth, settings), m, kTruth).translation_error;
  }
  EXPECT_LT(error_with, error_without);
}

TEST(MotionOnlyBa, SameInputSameResult) {
  const Camera cam = Camera::freiburg3();
  const Matches m = make_matches(cam, kTruth, 200, 0.2, 3);
  const Eigen::Isometry3d guess = kTruth * pose({1, 0, 0}, 2, {0.02, 0, 0});
  const PoseRefinement a = motion_only_ba(m.observations, cam, guess, MotionBaSettings{});
  const PoseRefinement b = motion_only_ba(m.observations, cam, guess, MotionBaSettings{});
  EXPECT_EQ(a.T_w_c.matrix(), b.T_w_c.matrix());
  EXPECT_EQ(a.inliers, b.inliers);
}

TEST(MotionOnlyBa, TooFewPointsFailsCleanly) {
  const Camera cam = Camera::freiburg3();
  const Matches m = make_matches(cam, kTruth, 5, 0, 4);
  const PoseRefinement r = motion_only_ba(m.observations, cam, kTruth, MotionBaSettings{});
  EXPECT_FALSE(r.ok);  // 5 < min_inliers = 10
  EXPECT_FALSE(motion_only_ba({}, cam, kTruth, MotionBaSettings{}).ok);
}

TEST(MotionOnlyBa, PointsBehindTheCameraAreOutliers) {
  const Camera cam = Camera::freiburg3();
  Matches m = make_matches(cam, kTruth, 50, 0, 5);
  PointObservation behind = m.observations[0];
  behind.p_w = kTruth * Eigen::Vector3d(0.1, 0.1, -2.0);
  m.observations.push_back(behind);
  const PoseRefinement r = motion_only_ba(m.observations, cam, kTruth, MotionBaSettings{});
  ASSERT_TRUE(r.ok);
  EXPECT_FALSE(r.inliers.back());
}

}  // namespace
}  // namespace slamkit
