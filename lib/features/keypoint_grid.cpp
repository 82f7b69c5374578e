#include "features/keypoint_grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamkit {

KeypointGrid::KeypointGrid(std::vector<Eigen::Vector2d> points, double cell_size)
    : cell_size_(cell_size) {
  if (cell_size <= 0) throw std::invalid_argument("KeypointGrid: cell size must be positive");
  if (points.empty()) return;
  // Bounds from the points themselves: undistorted keypoints can leave the image rectangle.
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const Eigen::Vector2d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  origin_ = lo;
  far_corner_ = hi;
  cols_ = static_cast<int>(std::floor((hi.x() - lo.x()) / cell_size_)) + 1;
  rows_ = static_cast<int>(std::floor((hi.y() - lo.y()) / cell_size_)) + 1;
  // Counting sort by cell; within a cell the indices stay ascending.
  std::vector<int> cell_of(points.size());
  cell_start_.assign(static_cast<size_t>(cols_) * rows_ + 1, 0);
  for (size_t i = 0; i < points.size(); ++i) {
    cell_of[i] = row(points[i].y()) * cols_ + column(points[i].x());
    ++cell_start_[cell_of[i] + 1];
  }
  for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  std::vector<int> next(cell_start_.begin(), cell_start_.end() - 1);
  entries_.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    entries_[next[cell_of[i]]++] = {points[i].x(), points[i].y(), static_cast<int>(i)};
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
  if (entries_.empty() || radius < 0) return;
  const Eigen::Vector2d lo = centre.array() - radius, hi = centre.array() + radius;
  // A search box that misses the points' bounds finds nothing (most map points projected
  // outside the image do).
  if ((hi.array() < origin_.array()).any() || (lo.array() > far_corner_.array()).any()) return;
  const int first_column = column(lo.x()), last_column = column(hi.x());
  const double radius2 = radius * radius;
  for (int r = row(lo.y()); r <= row(hi.y()); ++r) {
    const int begin = cell_start_[r * cols_ + first_column];
    const int end = cell_start_[r * cols_ + last_column + 1];
    for (int e = begin; e < end; ++e) {
      const double dx = entries_[e].x - centre.x(), dy = entries_[e].y - centre.y();
      if (dx * dx + dy * dy <= radius2) found.push_back(entries_[e].index);
    }
  }
}

}  // namespace slamkit
