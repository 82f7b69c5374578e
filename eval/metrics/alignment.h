#pragma once
// Aligning an estimate to groundtruth before measuring absolute error: closed-form least
// squares on positions (Umeyama, which equals the benchmark's Horn method for SE(3)).
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/association.h"
#include "core/trajectory.h"

namespace slamkit::eval {

enum class AlignMethod { kSe3, kSim3, kTranslation, kNone };

// Rotational statistics are withheld above this ambiguity (see Alignment). A trajectory
// with a few centimetres of error over a metre of motion has well under a degree; fr1/xyz,
// a short motion along the axes, has 4-6 deg; nine frames of fr1/desk have tens.
constexpr double kMaxRotationAmbiguityDeg = 10.0;

// x -> scale * rotation * x + translation, applied to estimated poses.
struct Alignment {
  AlignMethod method = AlignMethod::kNone;
  size_t poses_used = 0;  // pairs the alignment was computed from
  double scale = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  // How well the positions fix the rotation (se3/sim3 on 3 or more pairs; 0 otherwise): the
  // angle about the estimate's weakest axis (the long axis of its positions) that doubles
  // the mean squared residual, atan(residual rms / rms distance from that axis). Positions
  // on a line leave the rotation about it free (90 deg); with real noise, nearly collinear
  // positions (a short, straight piece of motion) do almost as badly.
  double rotation_ambiguity_deg = 0.0;

  bool rotation_well_determined() const {
    return rotation_ambiguity_deg <= kMaxRotationAmbiguityDeg;
  }
  Eigen::Vector3d apply(const Eigen::Vector3d& p) const {
    return scale * rotation * p + translation;
  }
  // Rotates the orientation and maps the position; the pose stays rigid (scale only moves it).
  Eigen::Isometry3d apply(const Eigen::Isometry3d& T_w_c) const;
};

// Aligns the estimate onto groundtruth using the matched `pairs` (first: gt index, second: est
// index), the first `first_n` of them (0 = all). first_n == 1 aligns the first poses (origin
// alignment: full pose for se3/sim3, scale 1). Throws InputError, naming the file at fault,
// when the alignment is undetermined: se3/sim3 on exactly 2 pairs (the rotation about the line
// through them is free), or positions that never move.
Alignment align(const Trajectory& gt, const Trajectory& est, const std::vector<IndexPair>& pairs,
                AlignMethod method, size_t first_n = 0, const std::string& gt_name = "groundtruth",
                const std::string& est_name = "estimate");

std::string to_string(AlignMethod method);
AlignMethod parse_align_method(const std::string& text);  // se3, sim3, translation, none

}  // namespace slamkit::eval
