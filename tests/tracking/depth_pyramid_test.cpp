#include "tracking/depth_pyramid.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

TEST(DepthPyramid, DownsamplingKeepsMeasuredDepthsAndIgnoresHoles) {
  // Blocks: all valid; one hole; an edge between 1 m and 3 m; all holes.
  const cv::Mat depth = (cv::Mat_<float>(2, 8) << 1.0f, 1.2f, 2.0f, 0.0f, 1.0f, 3.0f, 0, 0,  //
                         1.1f, 1.3f, 2.2f, 2.4f, 1.0f, 0.0f, 0, 0);
  const cv::Mat half = downsample_depth(depth);
  ASSERT_EQ(half.size(), cv::Size(4, 1));
  EXPECT_FLOAT_EQ(half.at<float>(0, 0), 1.1f);  // lower median of 1.0 1.1 1.2 1.3
  EXPECT_FLOAT_EQ(half.at<float>(0, 1), 2.2f);  // median of the 3 valid
  EXPECT_FLOAT_EQ(half.at<float>(0, 2), 1.0f);  // a measured depth, not the 1.67 m average
  EXPECT_FLOAT_EQ(half.at<float>(0, 3), 0.0f);
}

TEST(DepthPyramid, LevelsHalveImageAndCamera) {
  const cv::Mat depth(480, 640, CV_32F, cv::Scalar(1.5));
  const auto pyramid = depth_pyramid(depth, 3);
  ASSERT_EQ(pyramid.size(), 3u);
  EXPECT_EQ(pyramid[2].size(), cv::Size(160, 120));
  const Camera cam = Camera::freiburg3();
  const Camera half = camera_at_level(cam, 1);
  EXPECT_EQ(half.width, 320);
  EXPECT_DOUBLE_EQ(half.fx, cam.fx / 2);
  // A point seen at the centre of the 2x2 block (2u + 0.5, 2v + 0.5) is at (u, v) a level up.
  const Eigen::Vector3d p = cam.back_project(Eigen::Vector2d(100.5, 60.5), 2.0);
  EXPECT_LT((half.project(p) - Eigen::Vector2d(50, 30)).norm(), 1e-12);
}

}  // namespace
}  // namespace slamkit
