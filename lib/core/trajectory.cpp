#include "core/trajectory.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/pose.h"

namespace slamkit {

Trajectory::Trajectory(const std::vector<StampedPose>& poses) {
  std::vector<size_t> order(poses.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return poses[a].stamp < poses[b].stamp; });
  reserve(poses.size());
  for (size_t k : order) push_back(poses[k].stamp, poses[k].T_w_c);
}

Trajectory::Trajectory(std::vector<double> stamps, std::vector<Eigen::Vector3d> positions,
                       std::vector<Eigen::Quaterniond> orientations)
    : stamps_(std::move(stamps)),
      positions_(std::move(positions)),
      orientations_(std::move(orientations)) {
  if (positions_.size() != stamps_.size() || orientations_.size() != stamps_.size())
    throw std::invalid_argument("Trajectory: arrays differ in size");
  if (!std::is_sorted(stamps_.begin(), stamps_.end()))
    throw std::invalid_argument("Trajectory: stamps must not decrease");
}

Trajectory::Trajectory(std::vector<double> stamps, std::vector<Eigen::Vector3d> positions,
                       std::vector<Eigen::Matrix3d> rotations_as_written)
    : stamps_(std::move(stamps)),
      positions_(std::move(positions)),
      rotations_as_written_(std::move(rotations_as_written)),
      keeps_matrices_(true) {
  if (positions_.size() != stamps_.size() || rotations_as_written_.size() != stamps_.size())
    throw std::invalid_argument("Trajectory: arrays differ in size");
  if (!std::is_sorted(stamps_.begin(), stamps_.end()))
    throw std::invalid_argument("Trajectory: stamps must not decrease");
}

void Trajectory::push_back(double stamp, const Eigen::Isometry3d& T_w_c) {
  // The same quaternion pose_to_tum writes, so a written trajectory is unchanged by storage.
  if (keeps_matrices_) {
    append(stamp, T_w_c.translation());
    rotations_as_written_.push_back(T_w_c.linear());
    return;
  }
  push_back(stamp, T_w_c.translation(), Eigen::Quaterniond(T_w_c.linear()));
}

void Trajectory::push_back(double stamp, const Eigen::Vector3d& position,
                           const Eigen::Quaterniond& orientation) {
  append(stamp, position);
  if (keeps_matrices_) {
    rotations_as_written_.push_back(orientation.toRotationMatrix());
  } else {
    orientations_.push_back(orientation);
  }
}

void Trajectory::append(double stamp, const Eigen::Vector3d& position) {
  if (!stamps_.empty() && stamp < stamps_.back())
    throw std::invalid_argument("Trajectory::push_back: stamps must not decrease");
  stamps_.push_back(stamp);
  positions_.push_back(position);
}

void Trajectory::reserve(size_t n) {
  stamps_.reserve(n);
  positions_.reserve(n);
  if (keeps_matrices_) {
    rotations_as_written_.reserve(n);
  } else {
    orientations_.reserve(n);
  }
}

Eigen::Isometry3d Trajectory::pose(size_t i) const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = keeps_matrices_ ? rotations_as_written_[i] : orientations_[i].toRotationMatrix();
  T.translation() = positions_[i];
  return T;
}

Eigen::Quaterniond Trajectory::orientation(size_t i) const {
  return keeps_matrices_ ? quaternion_from_matrix(rotations_as_written_[i]) : orientations_[i];
}

std::vector<StampedPose> Trajectory::poses() const {
  std::vector<StampedPose> out(size());
  for (size_t i = 0; i < size(); ++i) out[i] = (*this)[i];
  return out;
}

std::optional<size_t> Trajectory::nearest(double t, double max_diff) const {
  if (stamps_.empty()) return std::nullopt;
  auto it = std::lower_bound(stamps_.begin(), stamps_.end(), t);
  size_t best = it == stamps_.end() ? stamps_.size() - 1 : size_t(it - stamps_.begin());
  if (best > 0 && std::abs(stamps_[best - 1] - t) <= std::abs(stamps_[best] - t)) --best;
  if (std::abs(stamps_[best] - t) > max_diff) return std::nullopt;
  return best;
}

double Trajectory::path_length() const {
  double length = 0;
  for (size_t i = 1; i < positions_.size(); ++i)
    length += (positions_[i] - positions_[i - 1]).norm();
  return length;
}

}  // namespace slamkit
