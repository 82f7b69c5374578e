#include "features/image_pyramid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "features/area_downscale.h"

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
  EXPECT_EQ(
      cv::norm(area_downscale(grey, pyramid.levels[2].size()), pyramid.levels[2], cv::NORM_INF),
      0.0);
}

// Reference: the exact area mean in doubles, straight from the definition.
cv::Mat exact_area_mean(const cv::Mat& grey, cv::Size size) {
  const double sx = static_cast<double>(grey.cols) / size.width;
  const double sy = static_cast<double>(grey.rows) / size.height;
  const auto overlap = [](int i, double begin, double end) {
    return std::max(0.0, std::min<double>(i + 1, end) - std::max<double>(i, begin));
  };
  cv::Mat mean(size, CV_64F);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      double sum = 0;
      for (int v = 0; v < grey.rows; ++v) {
        const double wy = overlap(v, y * sy, (y + 1) * sy);
        if (wy == 0) continue;
        for (int u = 0; u < grey.cols; ++u) {
          sum += wy * overlap(u, x * sx, (x + 1) * sx) * grey.at<uchar>(v, u);
        }
      }
      mean.at<double>(y, x) = sum / (sx * sy);
    }
  }
  return mean;
}

TEST(AreaDownscale, ThreePixelsToTwoByHand) {
  // Output 0 covers [0, 1.5): (0 * 1 + 90 * 0.5) / 1.5 = 30; output 1 covers [1.5, 3):
  // (90 * 0.5 + 180 * 1) / 1.5 = 150.
  const cv::Mat row = (cv::Mat_<uchar>(1, 3) << 0, 90, 180);
  const cv::Mat shrunk = area_downscale(row, {2, 1});
  EXPECT_EQ(shrunk.at<uchar>(0, 0), 30);
  EXPECT_EQ(shrunk.at<uchar>(0, 1), 150);
}

TEST(AreaDownscale, RoundsTheExactAreaMeanAndAgreesWithOpenCv) {
  cv::Mat noise(96, 128, CV_8UC1);
  cv::RNG rng(3);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  for (const cv::Size size : {cv::Size(107, 80), cv::Size(89, 67), cv::Size(74, 56),
                              cv::Size(128, 50), cv::Size(31, 96), cv::Size(1, 1)}) {
    const cv::Mat ours = area_downscale(noise, size);
    ASSERT_EQ(ours.size(), size);
    cv::Mat exact, error;
    exact_area_mean(noise, size).convertTo(exact, CV_64F);
    cv::Mat ours64;
    ours.convertTo(ours64, CV_64F);
    cv::absdiff(ours64, exact, error);
    double worst = 0;
    cv::minMaxLoc(error, nullptr, &worst);
    EXPECT_LE(worst, 0.5 + 0.02) << size;  // the nearest grey level, up to the weights' rounding
    cv::Mat opencv;
    cv::resize(noise, opencv, size, 0, 0, cv::INTER_AREA);
    EXPECT_LE(cv::norm(opencv, ours, cv::NORM_INF), 1.0) << size;
  }
}

TEST(AreaDownscale, KeepsAConstantImageAndRejectsUpscaling) {
  const cv::Mat flat(48, 64, CV_8UC1, cv::Scalar(77));
  EXPECT_EQ(cv::norm(area_downscale(flat, {53, 40}), cv::Mat(40, 53, CV_8UC1, cv::Scalar(77)),
                     cv::NORM_INF),
            0.0);
  EXPECT_THROW(area_downscale(flat, {65, 40}), std::invalid_argument);
  EXPECT_THROW(area_downscale(flat, {0, 40}), std::invalid_argument);
  EXPECT_THROW(area_downscale(cv::Mat(4, 4, CV_16UC1), {2, 2}), std::invalid_argument);
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
