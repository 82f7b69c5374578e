#pragma once
// Keypoints bucketed into square cells, to find those near a position fast (guided matching).
#include <Eigen/Core>
#include <vector>

namespace slamkit {

class KeypointGrid {
 public:
  // Takes its own copy of the positions (undistorted keypoints, usually).
  explicit KeypointGrid(std::vector<Eigen::Vector2d> points, double cell_size = 10);

  // Indices of the points at most `radius` from `centre`, ascending.
  std::vector<int> within(const Eigen::Vector2d& centre, double radius) const;
  // The same into `found` (cleared first), so that a caller asking many times reuses it.
  void within(const Eigen::Vector2d& centre, double radius, std::vector<int>& found) const;

 private:
  int column(double x) const;
  int row(double y) const;

  std::vector<Eigen::Vector2d> points_;
  double cell_size_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();  // corner of cell (0, 0)
  Eigen::Vector2d far_corner_ = Eigen::Vector2d::Zero();  // the points' largest x and y
  int cols_ = 0, rows_ = 0;
  std::vector<std::vector<int>> cells_;  // row-major
};

}  // namespace slamkit
