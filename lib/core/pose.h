#pragma once
// Poses are Eigen::Isometry3d named T_a_b (maps points in frame b into frame a);
// T_w_c is world-from-camera, as TUM groundtruth stores it.
#include <Eigen/Geometry>
#include <array>
#include <optional>

namespace slamkit {

// A pose from TUM's "tx ty tz qx qy qz qw". The quaternion is normalised; nullopt when any
// value is non-finite or the quaternion has (near) zero norm, for the caller to report.
std::optional<Eigen::Isometry3d> pose_from_tum(const std::array<double, 7>& values);

// The TUM fields of a pose, quaternion with qw >= 0 so that output is canonical.
std::array<double, 7> pose_to_tum(const Eigen::Isometry3d& T);

// The pose with its rotation projected back onto SO(3). Chains of products drift off it by
// rounding, and Isometry3d::inverse() (a transpose) then amplifies the drift: tracking
// normalises every pose it keeps.
Eigen::Isometry3d orthonormalised(const Eigen::Isometry3d& T);

// Rotation angle of a pose in radians, in [0, pi], robust near 0 and pi.
double rotation_angle(const Eigen::Isometry3d& T);

}  // namespace slamkit
