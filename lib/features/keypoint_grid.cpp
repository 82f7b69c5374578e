#include "features/keypoint_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamkit {

KeypointGrid::KeypointGrid(std::vector<Eigen::Vector2d> points, double cell_size)
    : points_(std::move(points)), cell_size_(cell_size) {
  if (cell_size <= 0) throw std::invalid_argument("KeypointGrid: cell size must be positive");
  if (points_.empty()) return;
  // Bounds from the points themselves: undistorted keypoints can leave the image rectangle.
  Eigen::Vector2d lo = points_[0], hi = points_[0];
  for (const Eigen::Vector2d& p : points_) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  origin_ = lo;
  far_corner_ = hi;
  cols_ = static_cast<int>(std::floor((hi.x() - lo.x()) / cell_size_)) + 1;
  rows_ = static_cast<int>(std::floor((hi.y() - lo.y()) / cell_size_)) + 1;
  cells_.resize(static_cast<size_t>(cols_) * rows_);
  for (size_t i = 0; i < points_.size(); ++i) {
    cells_[row(points_[i].y()) * cols_ + column(points_[i].x())].push_back(static_cast<int>(i));
  }
}

int KeypointGrid::column(double x) const {
  return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / cell_size_)), 0, cols_ - 1);
}

int KeypointGrid::row(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / cell_size_)), 0, rows_ - 1);
}

std::vector<int> KeypointGrid::within(const Eigen::Vector2d& centre, double radius) const {
  std::vector<int> found;
  within(centre, radius, found);
  return found;
}

void KeypointGrid::within(const Eigen::Vector2d& centre, double radius,
                          std::vector<int>& found) const {
  found.clear();
  if (points_.empty() || radius < 0) return;
  const Eigen::Vector2d lo = centre.array() - radius, hi = centre.array() + radius;
  // A search box that misses the points' bounds finds nothing (most map points projected
  // outside the image do).
  if ((hi.array() < origin_.array()).any() || (lo.array() > far_corner_.array()).any()) return;
  for (int r = row(lo.y()); r <= row(hi.y()); ++r) {
    for (int c = column(lo.x()); c <= column(hi.x()); ++c) {
      for (int i : cells_[r * cols_ + c]) {
        if ((points_[i] - centre).squaredNorm() <= radius * radius) found.push_back(i);
      }
    }
  }
  std::sort(found.begin(), found.end());
}

}  // namespace slamkit
