#pragma once
// Which trajectory format a file is in (TUM, KITTI poses, EuRoC CSV), given or detected from
// its first data line, and reading a file in any of them.
#include <filesystem>
#include <optional>
#include <string>

#include "io/trajectory_io.h"

namespace slamkit {

enum class TrajectoryFormat { kTum, kKitti, kEuroc };

std::string to_string(TrajectoryFormat format);
TrajectoryFormat parse_trajectory_format(const std::string& text);  // tum, kitti, euroc

// From the content: a '#timestamp' header with commas, or a first data line of >= 8
// comma-separated fields with an integer stamp beyond 1e11 (or a count other than 8 and 12)
// -> euroc; else 12 fields -> kitti; else tum (the default, whose reader then names a line of
// another field count). InputError naming file and line for the one real ambiguity: 8 or 12
// comma-separated fields whose first is an integer of at most 1e11 (tum or kitti vs euroc).
TrajectoryFormat detect_trajectory_format(const std::filesystem::path& path);

// Reads `path` in `format` (detected when unset). `kitti_times` is the times.txt of KITTI files.
TrajectoryFile read_trajectory(const std::filesystem::path& path,
                               std::optional<TrajectoryFormat> format,
                               const TrajectoryReadOptions& options,
                               const std::optional<std::filesystem::path>& kitti_times);

}  // namespace slamkit
