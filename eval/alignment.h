#pragma once
// Aligning an estimate to groundtruth before measuring absolute error: closed-form least
// squares on positions (Umeyama, which equals the benchmark's Horn method for SE(3)).
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace slamkit::eval {

enum class AlignMethod { kSe3, kSim3, kTranslation, kNone };

// x -> scale * rotation * x + translation, applied to estimated poses.
struct Alignment {
  AlignMethod method = AlignMethod::kNone;
  size_t poses_used = 0;  // pairs the alignment was computed from
  double scale = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const {
    return scale * rotation * p + translation;
  }
  // Rotates the orientation and maps the position; the pose stays rigid (scale only moves it).
  Eigen::Isometry3d apply(const Eigen::Isometry3d& T_w_c) const;
};

// Aligns `est` onto `gt` (matched pose lists of equal length) with the first `first_n` pairs
// (0 = all). first_n == 1 aligns the first poses (origin alignment: full pose for se3/sim3,
// scale 1); first_n == 2 cannot fix a rotation and is rejected for se3/sim3.
Alignment align(const std::vector<Eigen::Isometry3d>& est, const std::vector<Eigen::Isometry3d>& gt,
                AlignMethod method, size_t first_n = 0);

std::string to_string(AlignMethod method);
AlignMethod parse_align_method(const std::string& text);  // se3, sim3, translation, none

}  // namespace slamkit::eval
