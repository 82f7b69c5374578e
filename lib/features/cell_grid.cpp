#include "features/cell_grid.h"

#include <algorithm>

namespace slamkit {

CellGrid CellGrid::over(const cv::Rect& region, int cell_size) {
  CellGrid grid;
  grid.region = region;
  grid.cols = std::max(1, cvRound(static_cast<double>(region.width) / cell_size));
  grid.rows = std::max(1, cvRound(static_cast<double>(region.height) / cell_size));
  return grid;
}

cv::Rect CellGrid::cell(int index) const {
  const int c = index % cols, r = index / cols;
  const int x0 = region.x + c * region.width / cols, x1 = region.x + (c + 1) * region.width / cols;
  const int y0 = region.y + r * region.height / rows,
            y1 = region.y + (r + 1) * region.height / rows;
  return {x0, y0, x1 - x0, y1 - y0};
}

int CellGrid::index_of(cv::Point p) const {
  // Inverse of cell(): column c starts at floor(c w / cols), so the column of offset d is the
  // largest c with c w < (d + 1) cols.
  const auto slot = [](int d, int n, int length) {
    return ((d + 1) * n + length - 1) / length - 1;
  };
  const int c = slot(p.x - region.x, cols, region.width);
  const int r = slot(p.y - region.y, rows, region.height);
  return r * cols + c;
}

}  // namespace slamkit
