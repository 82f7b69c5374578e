#include "features/image_pyramid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace slamkit {
namespace {

cv::Mat ramp_image() {
  cv::Mat image(480, 640, CV_8UC1);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) image.at<uchar>(v, u) = static_cast<uchar>((u + v) % 256);
  }
  return image;
}

TEST(ImagePyramid, LevelSizesAndScalesFollowTheFactor) {
  const ImagePyramid pyramid = build_pyramid(ramp_image(), 4, 1.2);
  ASSERT_EQ(pyramid.size(), 4);
  const int widths[] = {640, 533, 444, 370}, heights[] = {480, 400, 333, 278};
  for (int l = 0; l < 4; ++l) {
    EXPECT_EQ(pyramid.levels[l].cols, widths[l]) << "level " << l;
    EXPECT_EQ(pyramid.levels[l].rows, heights[l]) << "level " << l;
    EXPECT_EQ(pyramid.levels[l].type(), CV_8UC1);
    EXPECT_NEAR(pyramid.scales[l], std::pow(1.2, l), 1e-12);
  }
}

TEST(ImagePyramid, LevelsAreAreaResizedFromLevelZero) {
  const cv::Mat grey = ramp_image();
  const ImagePyramid pyramid = build_pyramid(grey, 3, 1.2);
  cv::Mat expected;
  cv::resize(grey, expected, pyramid.levels[2].size(), 0, 0, cv::INTER_AREA);
  EXPECT_EQ(cv::norm(expected, pyramid.levels[2], cv::NORM_INF), 0.0);
}

TEST(ImagePyramid, CoordinateMappingRoundTripsAndMatchesTheResize) {
  const ImagePyramid pyramid = build_pyramid(ramp_image(), 4, 1.2);
  const cv::Point2f p(100.0f, 200.0f);
  for (int l = 0; l < 4; ++l) {
    const cv::Point2f back = pyramid.to_level0(pyramid.from_level0(p, l), l);
    EXPECT_NEAR(back.x, p.x, 1e-3);
    EXPECT_NEAR(back.y, p.y, 1e-3);
  }
  // The image edges map onto each other (cv::resize's pixel-centre convention), which the
  // nominal 1.2^3 = 1.728 would miss: the level is 370 px wide, 640 / 370 = 1.7297.
  const cv::Point2f corner = pyramid.to_level0({369.5f, 277.5f}, 3);
  EXPECT_NEAR(corner.x, 639.5, 1e-3);
  EXPECT_NEAR(corner.y, 479.5, 1e-3);
  const cv::Point2f origin = pyramid.to_level0({-0.5f, -0.5f}, 3);
  EXPECT_NEAR(origin.x, -0.5, 1e-3);
  EXPECT_NEAR(origin.y, -0.5, 1e-3);
}

}  // namespace
}  // namespace slamkit
