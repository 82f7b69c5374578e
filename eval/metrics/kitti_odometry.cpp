#include "eval/metrics/kitti_odometry.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace slamkit::eval {
namespace {

constexpr double kLengths[] = {100, 200, 300, 400, 500, 600, 700, 800};
constexpr size_t kStep = 10;  // first frames: every 10th (1 s of KITTI's 10 Hz)
constexpr double kRadToDeg = 180.0 / M_PI;

// Path distance of each frame from frame 0, along groundtruth.
std::vector<double> path_distances(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<double> distance(poses.size(), 0.0);
  for (size_t i = 1; i < poses.size(); ++i)
    distance[i] =
        distance[i - 1] + (poses[i].translation() - poses[i - 1].translation()).norm();
  return distance;
}

// The first frame from `first` on whose distance exceeds the first's by more than `length`.
std::optional<size_t> segment_end(const std::vector<double>& distance, size_t first,
                                  double length) {
  const auto it = std::upper_bound(distance.begin() + first, distance.end(),
                                   distance[first] + length);
  if (it == distance.end()) return std::nullopt;
  return size_t(it - distance.begin());
}

// The devkit inverts its matrices in general, not by transposing the rotation: the same for a
// rotation, not for the 7-digit matrices of KITTI's files (see Trajectory).
Eigen::Matrix4d inverse(const Eigen::Isometry3d& pose) { return pose.matrix().inverse(); }

double rotation_angle(const Eigen::Matrix3d& R) {
  return std::acos(std::clamp(0.5 * (R.trace() - 1.0), -1.0, 1.0));
}

}  // namespace

KittiOdometryResult compute_kitti_odometry(const std::vector<Eigen::Isometry3d>& gt,
                                           const std::vector<Eigen::Isometry3d>& est) {
  KittiOdometryResult result;
  const std::vector<double> distance = path_distances(gt);
  if (!distance.empty()) result.path_m = distance.back();
  for (size_t first = 0; first < gt.size(); first += kStep) {
    for (double length : kLengths) {
      const auto last = segment_end(distance, first, length);
      if (!last) continue;
      const Eigen::Matrix4d gt_delta = inverse(gt[first]) * gt[*last].matrix();
      const Eigen::Matrix4d est_delta = inverse(est[first]) * est[*last].matrix();
      const Eigen::Matrix4d error = est_delta.inverse() * gt_delta;
      result.segments.push_back({first, *last, length,
                                 error.topRightCorner<3, 1>().norm() / length,
                                 rotation_angle(error.topLeftCorner<3, 3>()) / length});
    }
  }
  for (double length : kLengths) {
    KittiLengthError stats{length, 0, 0.0, 0.0};
    for (const KittiSegmentError& s : result.segments) {
      if (s.length_m != length) continue;
      ++stats.segments;
      stats.trans_pct += s.trans_per_m;
      stats.rot_deg_per_m += s.rot_rad_per_m;
    }
    if (stats.segments == 0) continue;
    stats.trans_pct *= 100.0 / double(stats.segments);
    stats.rot_deg_per_m *= kRadToDeg / double(stats.segments);
    result.lengths.push_back(stats);
  }
  for (const KittiSegmentError& s : result.segments) {
    result.trans_pct += s.trans_per_m;
    result.rot_deg_per_m += s.rot_rad_per_m;
  }
  if (!result.segments.empty()) {
    result.trans_pct *= 100.0 / double(result.segments.size());
    result.rot_deg_per_m *= kRadToDeg / double(result.segments.size());
  }
  return result;
}

}  // namespace slamkit::eval
