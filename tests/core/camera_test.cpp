#include "core/camera.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <random>

namespace slamkit {
namespace {

TEST(Camera, BackProjectionInvertsProjection) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 639), v(0, 479), z(0.1, 8.0);
  for (const Camera& cam : {Camera::freiburg1(), Camera::freiburg2(), Camera::freiburg3()}) {
    for (int k = 0; k < 1000; ++k) {
      const Eigen::Vector2d uv(u(rng), v(rng));
      const double depth = z(rng);
      const Eigen::Vector3d p = cam.back_project(uv, depth);
      EXPECT_NEAR(p.z(), depth, 1e-12);
      EXPECT_LT((cam.project(p) - uv).norm(), 1e-9);
    }
  }
}

TEST(Camera, PresetsCarryTheBenchmarkNumbers) {
  const Camera fr1 = Camera::freiburg1();
  EXPECT_DOUBLE_EQ(fr1.fx, 517.3);
  EXPECT_DOUBLE_EQ(fr1.cy, 255.3);
  EXPECT_DOUBLE_EQ(fr1.distortion.k3, 1.1633);
  const Camera fr2 = Camera::freiburg2();
  EXPECT_DOUBLE_EQ(fr2.fy, 521.0);
  EXPECT_DOUBLE_EQ(fr2.distortion.k2, -0.7849);
  EXPECT_TRUE(Camera::freiburg3().distortion.is_zero());
  EXPECT_DOUBLE_EQ(fr2.depth_scale, 5000.0);
}

TEST(Camera, KinectPresetsHaveARollingShutterAndNoTrustedDepthStamps) {
  for (const Camera& kinect : {Camera::freiburg1(), Camera::freiburg2()}) {
    EXPECT_DOUBLE_EQ(kinect.readout_time, 0.030) << kinect.name;
    EXPECT_FALSE(kinect.exact_depth_stamps) << kinect.name;
  }
  EXPECT_DOUBLE_EQ(Camera::freiburg3().readout_time, 0.0);  // not measured: no Freiburg 3 piece
}

TEST(Camera, PresetChosenFromTheFolderName) {
  EXPECT_EQ(Camera::preset_for_sequence("/d/rgbd_dataset_freiburg1_desk")->name, "freiburg1");
  EXPECT_EQ(Camera::preset_for_sequence("rgbd_dataset_freiburg2_desk_first50/")->name,
            "freiburg2");
  EXPECT_EQ(Camera::preset_for_sequence("x/rgbd_dataset_freiburg3_long_office")->name,
            "freiburg3");
  // Only the folder's own name counts, not a parent's.
  EXPECT_FALSE(Camera::preset_for_sequence("/data/freiburg1/my_sequence").has_value());
}

TEST(Camera, DistortionMatchesOpenCvProjectPoints) {
  for (const Camera& cam : {Camera::freiburg1(), Camera::freiburg2()}) {
    std::vector<cv::Point3d> points;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> xy(-0.6, 0.6), z(0.5, 5);
    for (int k = 0; k < 500; ++k) {
      const double depth = z(rng);
      points.emplace_back(xy(rng) * depth, xy(rng) * 0.75 * depth, depth);
    }
    std::vector<cv::Point2d> expected;
    const cv::Matx33d K(cam.fx, 0, cam.cx, 0, cam.fy, cam.cy, 0, 0, 1);
    const cv::Matx<double, 1, 5> d(cam.distortion.k1, cam.distortion.k2, cam.distortion.p1,
                                   cam.distortion.p2, cam.distortion.k3);
    cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, d, expected);
    for (size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector2d ours =
          cam.project_distorted({points[k].x, points[k].y, points[k].z});
      EXPECT_NEAR(ours.x(), expected[k].x, 1e-9);
      EXPECT_NEAR(ours.y(), expected[k].y, 1e-9);
    }
  }
}

TEST(Camera, UndistortionInvertsDistortionInsideTheImage) {
  const Camera cam = Camera::freiburg1();
  std::vector<Eigen::Vector2d> raw;
  std::vector<Eigen::Vector2d> ideal;
  for (double u = 20; u < 640; u += 60)
    for (double v = 20; v < 480; v += 60) {
      const Eigen::Vector2d uv(u, v);
      ideal.push_back(uv);
      raw.push_back(cam.project_distorted(cam.back_project(uv, 1.0)));
    }
  const auto undistorted = cam.undistort_pixels(raw);
  for (size_t k = 0; k < ideal.size(); ++k) EXPECT_LT((undistorted[k] - ideal[k]).norm(), 1e-6);
}

}  // namespace
}  // namespace slamkit
