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

// The unit quaternion of a rotation matrix by the formula Markley's method picks (the largest of
// the trace and the diagonal), as scipy's Rotation.from_matrix, which evo uses. Eigen's
// conversion takes the trace formula whenever the trace is positive: the two agree on a
// rotation, but on a matrix printed with 7 digits (KITTI's files), which is not quite one, they
// differ by about 1e-7. Written by hand for that choice.
Eigen::Quaterniond quaternion_from_matrix(const Eigen::Matrix3d& R);

}  // namespace slamkit
