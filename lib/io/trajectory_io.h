#pragma once
// TUM trajectory files: "timestamp tx ty tz qx qy qz qw" per line, T_w_c.
#include <filesystem>
#include <string>
#include <vector>

#include "core/trajectory.h"

namespace slamkit {

struct TrajectoryFile {
  Trajectory trajectory;
  int zero_quaternions_skipped = 0;   // the benchmark skips all-zero quaternions too
  int non_finite_lines_skipped = 0;   // NaN / inf values
  int duplicate_stamps_dropped = 0;  // earlier line of a repeated stamp (the later one wins)
  bool was_unsorted = false;          // the file was not in time order (now sorted)
  std::vector<std::string> warnings;  // one per skipped line or oddity, naming file and line
};

// Reads a trajectory. Lines with other than 8 fields, non-numbers and files with no pose are
// errors (InputError naming file and line). Lines with non-finite values or a zero
// quaternion are skipped, and of a repeated timestamp only the last line is kept (as the
// benchmark does; real TUM groundtruth has such repeats), each reported in warnings.
// Quaternions are normalised; unsorted files are sorted, with a warning.
TrajectoryFile read_tum_trajectory(const std::filesystem::path& path);

// Writes every number in the shortest fixed notation that reads back to the same double, so
// files round-trip exactly (TUM's "1305031453.359684" stays as it is). Creates the folder.
void write_tum_trajectory(const std::filesystem::path& path, const Trajectory& trajectory,
                          const std::string& header_comment = "");

}  // namespace slamkit
