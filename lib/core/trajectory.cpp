#include "core/trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamkit {

Trajectory::Trajectory(std::vector<StampedPose> poses) : poses_(std::move(poses)) {
  std::stable_sort(poses_.begin(), poses_.end(),
                   [](const StampedPose& a, const StampedPose& b) { return a.stamp < b.stamp; });
}

void Trajectory::push_back(double stamp, const Eigen::Isometry3d& T_w_c) {
  if (!poses_.empty() && stamp < poses_.back().stamp)
    throw std::invalid_argument("Trajectory::push_back: stamps must not decrease");
  poses_.push_back({stamp, T_w_c});
}

std::vector<double> Trajectory::stamps() const {
  std::vector<double> s(poses_.size());
  for (size_t i = 0; i < poses_.size(); ++i) s[i] = poses_[i].stamp;
  return s;
}

std::optional<size_t> Trajectory::nearest(double t, double max_diff) const {
  if (poses_.empty()) return std::nullopt;
  auto it = std::lower_bound(poses_.begin(), poses_.end(), t,
                             [](const StampedPose& p, double v) { return p.stamp < v; });
  size_t best = it == poses_.end() ? poses_.size() - 1 : size_t(it - poses_.begin());
  if (best > 0 && std::abs(poses_[best - 1].stamp - t) <= std::abs(poses_[best].stamp - t))
    --best;
  if (std::abs(poses_[best].stamp - t) > max_diff) return std::nullopt;
  return best;
}

double Trajectory::path_length() const {
  double length = 0;
  for (size_t i = 1; i < poses_.size(); ++i)
    length += (poses_[i].T_w_c.translation() - poses_[i - 1].T_w_c.translation()).norm();
  return length;
}

}  // namespace slamkit
