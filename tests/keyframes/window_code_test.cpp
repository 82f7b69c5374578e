#include "keyframes/window_code.h"

#include <gtest/gtest.h>

#include "features/equivalent_grey.h"
#include "io/tum_sequence.h"
#include "keyframes/keyframe_rule.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

// A frame's code as the pipeline makes it: from the pyramid of its equivalent grey.
WindowCode encode(const cv::Mat& bgr, const WindowPattern& pattern) {
  const KeyframeSettings settings;
  return encode_windows(
      build_pyramid(equivalent_grey(bgr), settings.pyramid_levels, settings.scale_factor), pattern);
}

cv::Mat two_halves(int boundary_x) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(50, 50, 50));
  image.colRange(0, boundary_x).setTo(cv::Scalar(200, 200, 200));
  return image;
}

TEST(WindowCode, BitCountMatchesTheLevelsWindows) {
  KeyframeSettings settings;
  const WindowPattern pattern({640, 480}, settings);
  // 640x480, 533x400, 444x333, 370x278 -> windows 320*240 + 266*200 + 222*166 + 185*139.
  EXPECT_EQ(pattern.total_bits(), size_t(76800 + 53200 + 36852 + 25715));
  EXPECT_EQ(encode(two_halves(320), pattern).bits, pattern.total_bits());
}

TEST(WindowCode, SimilarityCountsTheWindowsThatChanged) {
  KeyframeSettings settings;
  settings.pyramid_levels = 1;  // level 0 only: no resampling blur, so the answer is exact
  const WindowPattern pattern({640, 480}, settings);
  const WindowCode a = encode(two_halves(320), pattern);
  const WindowCode b = encode(two_halves(300), pattern);
  // The windows with x in [300, 320) flip: 10 per row over 240 rows, of 76,800.
  EXPECT_DOUBLE_EQ(window_similarity(a, b), 1.0 - 2400.0 / 76800.0);
  EXPECT_DOUBLE_EQ(window_similarity(a, a), 1.0);
}

TEST(WindowCode, PatternIsFixedBySeed) {
  KeyframeSettings settings;
  const WindowPattern p1({640, 480}, settings), p2({640, 480}, settings);
  settings.pattern_seed += 1;
  const WindowPattern p3({640, 480}, settings);
  int same12 = 0, same13 = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      same12 += p1.choice(0, x, y) == p2.choice(0, x, y);
      same13 += p1.choice(0, x, y) == p3.choice(0, x, y);
    }
  EXPECT_EQ(same12, 10000);
  EXPECT_LT(same13, 4000);  // about a quarter agree by chance
}

TEST(WindowCode, RealFramesGrowLessSimilarWithDistance) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence seq = TumSequence::open(folder);
  const WindowPattern pattern({640, 480}, KeyframeSettings{});
  const WindowCode first = encode(seq.load(0).rgb, pattern);
  const double near = window_similarity(first, encode(seq.load(1).rgb, pattern));
  const double far = window_similarity(first, encode(seq.load(49).rgb, pattern));
  EXPECT_GT(near, 0.85);
  EXPECT_LT(far, near);
}

TEST(KeyframeRule, TakesTheMinimumOverTheKeyframeAndItsNeighbours) {
  KeyframeSettings settings;
  settings.pyramid_levels = 1;
  const WindowPattern pattern({640, 480}, settings);
  const WindowCode same = encode(two_halves(320), pattern);
  const WindowCode shifted = encode(two_halves(300), pattern);
  const WindowCode moved = encode(two_halves(100), pattern);
  // `moved` differs from `same` in pixel columns 100..320, i.e. 110 of 320 window columns:
  // zeta = 1 - 110/320 = 0.656 < 0.7; from `shifted` in 100 of 320.
  const KeyframeDecision d = decide_keyframe(moved, {&same, &shifted}, 100, 100, settings);
  EXPECT_TRUE(d.is_keyframe);
  EXPECT_FALSE(d.forced_by_tracking);
  EXPECT_NEAR(d.similarity, 1.0 - 110.0 / 320.0, 1e-12);
  const KeyframeDecision close = decide_keyframe(shifted, {&same}, 100, 100, settings);
  EXPECT_FALSE(close.is_keyframe);
  EXPECT_NEAR(close.similarity, 1.0 - 10.0 / 320.0, 1e-12);
  // The tracking guard: fewer than half the reference keyframe's matches.
  const KeyframeDecision thin = decide_keyframe(shifted, {&same}, 40, 100, settings);
  EXPECT_TRUE(thin.forced_by_tracking);
  EXPECT_TRUE(thin.is_keyframe);
}

TEST(KeyframeRule, NeighboursAreAroundTheKeyframeAndBeforeTheCurrentFrame) {
  KeyframeSettings settings;
  settings.neighbour_frames = 1;
  EXPECT_EQ(keyframe_neighbours(5, 9, settings), (std::vector<size_t>{4, 5, 6}));
  EXPECT_EQ(keyframe_neighbours(5, 6, settings), (std::vector<size_t>{4, 5}));
  EXPECT_EQ(keyframe_neighbours(0, 3, settings), (std::vector<size_t>{0, 1}));
}

TEST(WindowCode, APyramidOfOtherSizesIsRefused) {
  const WindowPattern pattern({640, 480}, KeyframeSettings{});
  const ImagePyramid small = build_pyramid(cv::Mat(240, 320, CV_8UC1, cv::Scalar(9)), 4, 1.2);
  EXPECT_FALSE(fits(small, pattern));
  EXPECT_THROW(encode_windows(small, pattern), std::invalid_argument);
}

}  // namespace
}  // namespace slamkit
