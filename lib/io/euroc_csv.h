#pragma once
// EuRoC / ASL CSV trajectories (state_groundtruth_estimate0/data.csv and the like): a '#' header,
// then "timestamp [ns], p_x, p_y, p_z, q_w, q_x, q_y, q_z, ..." per line, T_w_c (body frame).
#include <filesystem>
#include <optional>
#include <string_view>

#include "io/trajectory_io.h"

namespace slamkit {

// Reads an ASL CSV file; columns after the 8th are ignored. The stamp is an integer number of
// nanoseconds (converted to seconds, exactly as --time-unit ns does). Errors (InputError naming
// file and line) as read_tum_trajectory's, with at least 8 fields a line, and a stamp that is not
// an integer or beyond int64. Only options.duplicates applies (the unit is always ns).
TrajectoryFile read_euroc_csv(const std::filesystem::path& path,
                              const TrajectoryReadOptions& options = {});

// Writes `trajectory` as an ASL CSV file with its header, each stamp as the nanosecond nearest
// to it, which reads back to the same stamp. (A double holds an epoch stamp to about 0.24 us, so
// a file's nanoseconds read and written again are not kept digit for digit.) InputError naming
// the file for a stamp beyond int64 nanoseconds.
void write_euroc_csv(const std::filesystem::path& path, const Trajectory& trajectory);

// The field as an integer count of nanoseconds, or nullopt when it is not one; `overflow` set
// when it is an integer beyond int64. Shared with format detection.
std::optional<long long> parse_nanoseconds(std::string_view text, bool* overflow = nullptr);

}  // namespace slamkit
