// Invalid depth counts on an image whose invalid pixels and edge region are known exactly.
#include "eval/sequence_stats/invalid_depth.h"

#include <gtest/gtest.h>

namespace slamkit::stats {
namespace {

TEST(InvalidDepth, CountsInvalidPixelsOverallAndNearTheDiscontinuityExactly) {
  // 1 m left of column 320, 2 m from it on; invalid: columns 100-109 (far from the step) and
  // column 320 (on it).
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(1.0));
  depth.colRange(320, 640).setTo(2.0);
  depth.colRange(100, 110).setTo(0.0);
  depth.col(320).setTo(0.0);
  const InvalidCounts c = count_invalid(depth, {3, 0.1});
  EXPECT_EQ(c.pixels, 640u * 480u);
  EXPECT_EQ(c.invalid, 11u * 480u);
  // A 7-wide window holds a 1 m column (<= 319) and a 2 m one (>= 321) from column 318 to 322.
  EXPECT_EQ(c.edge_pixels, 5u * 480u);
  EXPECT_EQ(c.edge_invalid, 480u);
  EXPECT_DOUBLE_EQ(c.share(), 11.0 / 640.0);
  EXPECT_DOUBLE_EQ(c.edge_region_share(), 5.0 / 640.0);
  EXPECT_DOUBLE_EQ(c.edge_share(), 1.0 / 5.0);
  EXPECT_DOUBLE_EQ(c.off_edge_share(), 10.0 / 635.0);

  InvalidCounts twice = c;
  twice += c;
  EXPECT_EQ(twice.invalid, 2 * c.invalid);
  EXPECT_DOUBLE_EQ(twice.edge_share(), c.edge_share());
}

TEST(InvalidDepth, SmoothSlopeAndAllInvalidHaveNoEdges) {
  cv::Mat slope(480, 640, CV_32F);
  for (int u = 0; u < 640; ++u) slope.col(u).setTo(1.0 + 0.001 * u);  // < 1% across a window
  EXPECT_EQ(count_invalid(slope, {}).edge_pixels, 0u);
  const InvalidCounts none = count_invalid(cv::Mat::zeros(480, 640, CV_32F), {});
  EXPECT_EQ(none.invalid, none.pixels);
  EXPECT_EQ(none.edge_pixels, 0u);
}

}  // namespace
}  // namespace slamkit::stats
