#pragma once
// A rectangle cut into near-square cells of about a given size (the last ones absorb rounding).
#include <opencv2/core.hpp>

namespace slamkit {

struct CellGrid {
  cv::Rect region;
  int cols = 1, rows = 1;

  static CellGrid over(const cv::Rect& region, int cell_size);

  int count() const { return cols * rows; }
  cv::Rect cell(int index) const;
  // Index of the cell holding p (p must lie in region).
  int index_of(cv::Point p) const;
};

}  // namespace slamkit
