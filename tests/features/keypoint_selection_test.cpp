#include "features/keypoint_selection.h"

#include <gtest/gtest.h>

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
