#include "features/keypoint_selection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace slamkit {
namespace {

TEST(KeypointSelection, LevelQuotasFollowAreaAndSumToTotal) {
  const std::vector<int> n = features_per_level(1000, 4, 1.2);
  EXPECT_EQ(std::accumulate(n.begin(), n.end(), 0), 1000);
  EXPECT_EQ(n[0], 398);
  EXPECT_EQ(n[1], 276);
  EXPECT_EQ(n[2], 192);
}

TEST(KeypointSelection, ShiTomasiEqualsOpenCvAtEveryBlockSize) {
  // Block sizes of one, two and four 8-lane chunks, up to the image border the contract allows.
  cv::Mat noise(60, 70, CV_8UC1);
  cv::RNG rng(5);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(noise, noise, {5, 5}, 1.0);
  for (const int block : {3, 7, 9, 31}) {
    cv::Mat dense;
    cv::cornerMinEigenVal(noise, dense, block, 3);
    const int r = block / 2 + 1;
    const std::vector<cv::Point> points = {
        {r, r}, {noise.cols - 1 - r, noise.rows - 1 - r}, {35, 30}, {r, noise.rows - 1 - r}};
    const std::vector<float> sparse = shi_tomasi_response(noise, points, block);
    for (size_t i = 0; i < points.size(); ++i) {
      const float expected = dense.at<float>(points[i]);
      EXPECT_NEAR(sparse[i], expected, 1e-4 * expected + 1e-7) << block << " at " << points[i];
    }
  }
  EXPECT_THROW(shi_tomasi_response(noise, {{20, 20}}, 8), std::invalid_argument);
  EXPECT_THROW(shi_tomasi_response(noise, {{20, 20}}, 33), std::invalid_argument);
}

TEST(KeypointSelection, NonMaximumSuppressionKeepsLocalPeaks) {
  const std::vector<cv::Point> points = {{10, 10}, {11, 10}, {12, 11}, {20, 20}, {21, 21}};
  const std::vector<float> responses = {1.0f, 3.0f, 2.0f, 5.0f, 5.0f};
  const std::vector<Corner> kept = suppress_non_maxima(points, responses, {40, 40});
  ASSERT_EQ(kept.size(), 2u);  // (11,10) beats both neighbours; of the tie the first stays
  EXPECT_EQ(kept[0].pt, cv::Point(20, 20));
  EXPECT_EQ(kept[1].pt, cv::Point(11, 10));
}

TEST(KeypointSelection, NonMaximumSuppressionEqualsBruteForce) {
  // Dense random candidates in a small window, responses from a few values so ties abound, in
  // a shuffled order; the reference compares every pair.
  cv::RNG rng(11);
  std::vector<cv::Point> points;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x)
      if (rng.uniform(0, 3) > 0) points.emplace_back(x, y);
  std::vector<float> responses;
  for (size_t i = 0; i < points.size(); ++i) responses.push_back(float(rng.uniform(0, 6)));
  for (size_t i = points.size(); i > 1; --i) {
    const size_t j = size_t(rng.uniform(0, int(i)));
    std::swap(points[i - 1], points[j]);
    std::swap(responses[i - 1], responses[j]);
  }
  std::vector<Corner> expected;
  for (size_t i = 0; i < points.size(); ++i) {
    bool is_max = true;
    for (size_t j = 0; j < points.size(); ++j) {
      const cv::Point d = points[j] - points[i];
      if (j == i || std::abs(d.x) > 1 || std::abs(d.y) > 1) continue;
      const bool earlier = d.y < 0 || (d.y == 0 && d.x < 0);
      if (responses[j] > responses[i] || (responses[j] == responses[i] && earlier)) is_max = false;
    }
    if (is_max) expected.push_back({points[i], responses[i]});
  }
  const std::vector<Corner> kept = suppress_non_maxima(points, responses, {30, 30});
  ASSERT_EQ(kept.size(), expected.size());
  std::vector<cv::Point> kept_points, expected_points;
  for (const Corner& c : kept) kept_points.push_back(c.pt);
  for (const Corner& c : expected) expected_points.push_back(c.pt);
  const auto raster = [](const cv::Point& a, const cv::Point& b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  };
  std::sort(kept_points.begin(), kept_points.end(), raster);
  std::sort(expected_points.begin(), expected_points.end(), raster);
  EXPECT_EQ(kept_points, expected_points);
  for (size_t i = 1; i < kept.size(); ++i) EXPECT_GE(kept[i - 1].response, kept[i].response);
}

TEST(KeypointSelection, SpreadCapsEachCellAtItsShare) {
  const CellGrid grid = CellGrid::over({0, 0, 100, 100}, 50);  // 2 x 2 cells
  std::vector<Corner> sorted;
  for (int i = 0; i < 40; ++i) sorted.push_back({{i % 40 + 1, 1}, 100.0f - i});  // strong, cell 0
  for (int i = 0; i < 3; ++i) sorted.push_back({{60 + i, 60}, 10.0f - i});       // weak, cell 3
  const std::vector<Corner> spread = select_spread(sorted, 10, grid, 1.0);
  // Fair share 10 / 2 occupied cells = 5: cell 0 gives 5, cell 3 all its 3.
  ASSERT_EQ(spread.size(), 8u);
  int in_cell3 = 0;
  for (const Corner& c : spread) in_cell3 += grid.index_of(c.pt) == 3;
  EXPECT_EQ(in_cell3, 3);
  EXPECT_EQ(select_strongest(sorted, 10).size(), 10u);
  for (const Corner& c : select_strongest(sorted, 10)) EXPECT_EQ(grid.index_of(c.pt), 0);
}

TEST(CellGrid, CellIndexInvertsTheCellRectangles) {
  const CellGrid grid = CellGrid::over({19, 19, 602, 442}, 30);
  EXPECT_EQ(grid.cols, 20);
  EXPECT_EQ(grid.rows, 15);
  for (int i = 0; i < grid.count(); ++i) {
    const cv::Rect cell = grid.cell(i);
    EXPECT_EQ(grid.index_of(cell.tl()), i);
    EXPECT_EQ(grid.index_of(cell.br() - cv::Point(1, 1)), i);
  }
}

}  // namespace
}  // namespace slamkit
