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

// Stored compactly (stamp, position, unit quaternion: 64 bytes a pose rather than 144 for a
// stamp and a 4x4 matrix), so a million-pose file costs 64 MB; poses are rebuilt on access.
// A trajectory read from rotation matrices (KITTI files) keeps them as written instead (104
// bytes a pose): their 7 printed digits leave R^T R - I at about 1e-7, and evo and the KITTI
// devkit compute with such matrices as they are, so pose() returns them for the evaluation to
// do the same, and orientation() their quaternion as scipy's Rotation.from_matrix gives it.
class Trajectory {
 public:
  Trajectory() = default;
  // Sorts by time (stable, so equal stamps keep their order).
  explicit Trajectory(const std::vector<StampedPose>& poses);
  // Takes parallel arrays already sorted by stamp, with unit quaternions (a file reader's).
  Trajectory(std::vector<double> stamps, std::vector<Eigen::Vector3d> positions,
             std::vector<Eigen::Quaterniond> orientations);
  // The same with rotation matrices, kept as written (near-rotations: a file reader's).
  Trajectory(std::vector<double> stamps, std::vector<Eigen::Vector3d> positions,
             std::vector<Eigen::Matrix3d> rotations_as_written);

  // Appends; the stamp must not be earlier than the last one.
  void push_back(double stamp, const Eigen::Isometry3d& T_w_c);
  // Appends a pose given as position and unit quaternion (what a TUM line holds).
  void push_back(double stamp, const Eigen::Vector3d& position,
                 const Eigen::Quaterniond& orientation);
  void reserve(size_t n);

  size_t size() const { return stamps_.size(); }
  bool empty() const { return stamps_.empty(); }
  // The pose rebuilt from its compact form (a value, not a reference into the trajectory), with
  // the rotation matrix as written when the trajectory keeps those.
  StampedPose operator[](size_t i) const { return {stamps_[i], pose(i)}; }
  Eigen::Isometry3d pose(size_t i) const;
  bool keeps_rotations_as_written() const { return keeps_matrices_; }
  double stamp(size_t i) const { return stamps_[i]; }
  const Eigen::Vector3d& position(size_t i) const { return positions_[i]; }
  Eigen::Quaterniond orientation(size_t i) const;
  std::vector<StampedPose> poses() const;
  const std::vector<double>& stamps() const { return stamps_; }
  double start_time() const { return stamps_.front(); }
  double end_time() const { return stamps_.back(); }

  // Index of the pose nearest in time to t if within max_diff seconds (the earlier on a tie).
  std::optional<size_t> nearest(double t, double max_diff) const;

  // Total length of the camera path in metres.
  double path_length() const;

 private:
  void append(double stamp, const Eigen::Vector3d& position);  // checks the stamp's order

  std::vector<double> stamps_;
  std::vector<Eigen::Vector3d> positions_;
  // One of the two holds a rotation a pose, the other is empty.
  std::vector<Eigen::Quaterniond> orientations_;
  std::vector<Eigen::Matrix3d> rotations_as_written_;
  bool keeps_matrices_ = false;
};

}  // namespace slamkit
