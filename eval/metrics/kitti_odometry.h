#pragma once
// The KITTI odometry benchmark's metric (devkit evaluate_odometry.cpp): relative pose errors
// over path segments of 100, 200, ..., 800 m of groundtruth, starting every 10th frame, as a
// translational error in % and a rotational error in deg/m, per length and overall.
#include <Eigen/Geometry>
#include <vector>

namespace slamkit::eval {

struct KittiSegmentError {
  size_t first = 0, last = 0;  // frames
  double length_m = 0;         // the nominal length (100, ..., 800)
  double trans_per_m = 0;      // |t_E| / length
  double rot_rad_per_m = 0;    // angle(R_E) / length
};

struct KittiLengthError {
  double length_m = 0;
  size_t segments = 0;
  double trans_pct = 0;      // mean trans_per_m x 100
  double rot_deg_per_m = 0;  // mean rot_rad_per_m in degrees
};

struct KittiOdometryResult {
  std::vector<KittiSegmentError> segments;
  std::vector<KittiLengthError> lengths;  // only lengths with at least one segment
  double trans_pct = 0;                   // mean over every segment (the devkit's stats.txt)
  double rot_deg_per_m = 0;
  double path_m = 0;  // the groundtruth's whole path
};

// `gt` and `est` are the same frames in order (poses T_w_c). For first frames 0, 10, 20, ...
// and each length L, the segment ends at the first frame whose groundtruth path distance from
// the first exceeds L (strictly, as the devkit); E = (est_f^-1 est_l)^-1 (gt_f^-1 gt_l).
// Computed in double where the devkit uses float. No segment (groundtruth path up to 100 m)
// leaves `segments` empty.
KittiOdometryResult compute_kitti_odometry(const std::vector<Eigen::Isometry3d>& gt,
                                           const std::vector<Eigen::Isometry3d>& est);

}  // namespace slamkit::eval
