// ORB match inliers: a textured plane seen from two known poses (the second image rendered by
// warping the first with the plane's homography) is explained by one motion; correspondences
// of which a known fraction is replaced by random pixels give that fraction of outliers.
#include "eval/sequence_stats/match_inliers.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "datasets/synth/sequence_writer.h"
#include "features/orb_extractor.h"

namespace slamkit::stats {
namespace {

// The synthetic sequences' camera: fx = fy = 525, 640 x 480, no distortion.
Camera pinhole() { return synth::synthetic_camera(); }

// T_c2_c1: a 3 degree turn and 4 cm sideways.
Eigen::Isometry3d second_pose() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(3.0 * M_PI / 180.0, Eigen::Vector3d(0.2, 1, 0.1).normalized())
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.04, -0.01, 0.005);
  return T;
}

cv::Mat texture(int seed) {
  cv::Mat coarse(120, 160, CV_8UC1), image;
  cv::RNG(uint64_t(seed)).fill(coarse, cv::RNG::UNIFORM, 0, 256);
  cv::resize(coarse, image, {640, 480}, 0, 0, cv::INTER_LINEAR);
  return image;
}

TEST(MatchInliers, WarpedPlaneIsExplainedByOneMotion) {
  const Camera camera = pinhole();
  const double plane_depth = 2.0;  // fronto-parallel in the first camera: n = z, d = 2 m
  const cv::Mat first = texture(5);
  // Points of the plane move as X2 = (R + t n^T / d) X1, so pixels by K (R + t n^T/d) K^-1.
  const Eigen::Isometry3d T = second_pose();
  Eigen::Matrix3d K;
  K << camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1;
  const Eigen::Matrix3d H =
      K * (T.linear() + T.translation() * Eigen::Vector3d(0, 0, 1).transpose() / plane_depth) *
      K.inverse();
  cv::Matx33d H_cv;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) H_cv(r, c) = H(r, c);
  cv::Mat second;
  cv::warpPerspective(first, second, H_cv, first.size(), cv::INTER_LINEAR);
  const cv::Mat depth(first.size(), CV_32F, cv::Scalar(plane_depth));

  const MatchInlierSettings settings;
  const FrameFeatures a = extract_orb(first, camera, settings.orb);
  const FrameFeatures b = extract_orb(second, camera, settings.orb);
  const PairInliers pair = match_inliers(a, depth, b, camera, settings);
  EXPECT_GT(pair.matches, 200u);
  EXPECT_EQ(pair.correspondences, pair.matches);  // depth everywhere
  ASSERT_TRUE(pair.fitted);
  EXPECT_GT(pair.share(), 0.95);

  // Against an unrelated texture, matches that survive are not one motion.
  const PairInliers unrelated =
      match_inliers(a, depth, extract_orb(texture(6), camera, settings.orb), camera, settings);
  EXPECT_LT(unrelated.fitted ? unrelated.share() : 0.0, 0.5);
}

TEST(MatchInliers, KnownShareOfRandomCorrespondencesAreOutliers) {
  const Camera camera = pinhole();
  const Eigen::Isometry3d T = second_pose();
  cv::RNG rng(9);
  std::vector<cv::Point3f> points;
  std::vector<cv::Point2f> pixels;
  while (points.size() < 200) {
    const Eigen::Vector3d p = camera.back_project(
        {rng.uniform(0.0, 639.0), rng.uniform(0.0, 479.0)}, rng.uniform(0.8, 3.5));
    const Eigen::Vector2d uv = camera.project(T * p);
    if (!camera.contains(uv)) continue;
    points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    pixels.emplace_back(float(uv.x()), float(uv.y()));
  }
  const MatchInlierSettings settings;
  EXPECT_EQ(pose_inliers(points, pixels, camera, settings), 200u);
  // Every third correspondence is made an outlier: alternately a random pixel and its true
  // pixel moved 6 px, just past the 2.45 px threshold. 67 outliers (a random pixel may land
  // near its true one by chance: a 1e-4 chance each).
  for (size_t i = 0; i < pixels.size(); i += 3) {
    const double angle = rng.uniform(0.0, 2 * M_PI);
    pixels[i] =
        i % 2 ? cv::Point2f(float(rng.uniform(0.0, 639.0)), float(rng.uniform(0.0, 479.0)))
              : pixels[i] + cv::Point2f(float(6 * std::cos(angle)), float(6 * std::sin(angle)));
  }
  const size_t inliers = pose_inliers(points, pixels, camera, settings);
  EXPECT_GE(inliers, 133u);
  EXPECT_LE(inliers, 134u);
}

}  // namespace
}  // namespace slamkit::stats
