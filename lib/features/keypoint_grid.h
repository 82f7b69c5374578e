#pragma once
// Keypoints bucketed into square cells, to find those near a position fast (guided matching).
#include <Eigen/Core>
#include <vector>

namespace slamkit {

class KeypointGrid {
 public:
  // Takes its own copy of the positions (undistorted keypoints, usually).
  explicit KeypointGrid(std::vector<Eigen::Vector2d> points, double cell_size = 10);

  // Indices of the points at most `radius` from `centre`, in grid order (row by row, then by
  // index within a cell): deterministic, but not sorted, as sorting cost more than the search.
  std::vector<int> within(const Eigen::Vector2d& centre, double radius) const;
  // The same into `found` (cleared first), so that a caller asking many times reuses it.
  void within(const Eigen::Vector2d& centre, double radius, std::vector<int>& found) const;

 private:
  struct Entry {  // a point as the search reads it: position and index side by side
    double x, y;
    int index;
  };

  int column(double x) const;
  int row(double y) const;

  double cell_size_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();      // corner of cell (0, 0)
  Eigen::Vector2d far_corner_ = Eigen::Vector2d::Zero();  // the points' largest x and y
  int cols_ = 0, rows_ = 0;
  // The points ordered by cell (row-major), so the cells a search box spans in one row are
  // one contiguous stretch: cell c holds entries_[cell_start_[c] .. cell_start_[c + 1]).
  std::vector<Entry> entries_;
  std::vector<int> cell_start_;
};

}  // namespace slamkit
