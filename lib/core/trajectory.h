#pragma once
// A trajectory: poses T_w_c with timestamps (seconds), kept sorted by time.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

namespace slamkit {

struct StampedPose {
  double stamp = 0;
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
};

class Trajectory {
 public:
  Trajectory() = default;
  // Sorts by time (stable, so equal stamps keep their order).
  explicit Trajectory(std::vector<StampedPose> poses);

  // Appends; the stamp must not be earlier than the last one.
  void push_back(double stamp, const Eigen::Isometry3d& T_w_c);

  size_t size() const { return poses_.size(); }
  bool empty() const { return poses_.empty(); }
  const StampedPose& operator[](size_t i) const { return poses_[i]; }
  const std::vector<StampedPose>& poses() const { return poses_; }
  std::vector<double> stamps() const;
  double start_time() const { return poses_.front().stamp; }
  double end_time() const { return poses_.back().stamp; }

  // Index of the pose nearest in time to t if within max_diff seconds.
  std::optional<size_t> nearest(double t, double max_diff) const;

  // Total length of the camera path in metres.
  double path_length() const;

 private:
  std::vector<StampedPose> poses_;
};

}  // namespace slamkit
