#pragma once
// KITTI odometry pose files: per line the 12 numbers of the row-major 3x4 [R|t] of T_w_c, no
// stamps. Stamps come from the sequence's times.txt (one time in seconds per line) or, without
// it, are the pose index in seconds.
#include <filesystem>
#include <optional>

#include "io/trajectory_io.h"

namespace slamkit {

// Reads a KITTI pose file; the trajectory keeps the rotation matrices as written. Errors
// (InputError naming file and line) as read_tum_trajectory's, with 12 fields a line, and a
// rotation block that is not a rotation (|R^T R - I| > 1e-3 or det R < 0). `times` (a times.txt) must hold as many stamps as the file has pose lines, in
// options.time_unit. Blank and '#' lines are skipped in both files (they do not count as
// poses); a pose or stamp that is NaN or inf skips the pose with a warning.
TrajectoryFile read_kitti_poses(const std::filesystem::path& path,
                                const std::optional<std::filesystem::path>& times,
                                const TrajectoryReadOptions& options = {});

// Writes `trajectory` as a KITTI pose file (each rotation as its matrix, every number in its
// shortest exact form) and, when `times` is given, its stamps as a times.txt; so that
// read_kitti_poses(path, times) gives the same stamps and positions back, the rotations exactly
// when the trajectory keeps them as written (one read from KITTI), else to rounding.
void write_kitti_poses(const std::filesystem::path& path, const Trajectory& trajectory,
                       const std::optional<std::filesystem::path>& times = std::nullopt);

}  // namespace slamkit
