#pragma once
// TUM trajectory files: "timestamp tx ty tz qx qy qz qw" per line, T_w_c.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/trajectory.h"

namespace slamkit {

// Unit of the timestamps in a file; they are converted to seconds on reading.
enum class TimeUnit { kSeconds, kMicroseconds, kNanoseconds };

// Which lines of a repeated timestamp are kept: the benchmark's dict-based reader keeps the
// last; evo keeps every line (each is a pose of its trajectory and is associated on its own).
enum class DuplicateStamps { kKeepLast, kKeepFirst, kKeepAll };

struct TrajectoryReadOptions {
  TimeUnit time_unit = TimeUnit::kSeconds;
  DuplicateStamps duplicates = DuplicateStamps::kKeepLast;
};

struct TrajectoryFile {
  Trajectory trajectory;
  int zero_quaternions_skipped = 0;   // the benchmark skips all-zero quaternions too
  int non_finite_lines_skipped = 0;   // NaN / inf values
  int duplicate_stamps_dropped = 0;   // lines of a repeated stamp that were not kept
  bool was_unsorted = false;          // the file was not in time order (now sorted)
  std::vector<std::string> warnings;  // one per skipped line or oddity, naming file and line
  std::string format = "tum";         // tum, kitti or euroc (trajectory_format.h)
};

// Values beyond this magnitude are rejected: no pose or time is that large, and squares of
// them would overflow the statistics to inf.
constexpr double kMaxTrajectoryValue = 1e100;
// A trajectory holds at most this many poses (28 hours at 100 Hz; about 200 bytes a pose while
// reading, so 2 GB at most), and its lines at most kMaxLineBytes (line_reader.h).
constexpr size_t kMaxTrajectoryPoses = 10'000'000;

// Reads a trajectory. Errors (InputError naming file and line): lines with other than 8
// fields, fields that are not wholly a number (a NUL byte inside one included), values beyond
// kMaxTrajectoryValue, files with no pose, more than kMaxTrajectoryPoses, lines too long. Lines
// with non-finite values or a zero quaternion are skipped, and of a repeated timestamp one line is
// kept (options.duplicates), each reported in warnings. A UTF-8 byte order mark is skipped;
// quaternions are normalised; unsorted files are sorted, with a warning. Input quoted in messages
// is escaped (printable).
TrajectoryFile read_tum_trajectory(const std::filesystem::path& path,
                                   const TrajectoryReadOptions& options = {});

// Writes every number in the shortest fixed notation that reads back to the same double, so
// files round-trip exactly (TUM's "1305031453.359684" stays as it is). Creates the folder.
void write_tum_trajectory(const std::filesystem::path& path, const Trajectory& trajectory,
                          const std::string& header_comment = "");

// `text` safe to print on a terminal: control bytes (ESC, BEL, NUL, ...; C1 controls in
// UTF-8) become \xNN, and text longer than `max_length` bytes is cut with "...".
std::string printable(std::string_view text, size_t max_length = 64);

std::string to_string(TimeUnit unit);
TimeUnit parse_time_unit(const std::string& text);  // s, us, ns
std::string to_string(DuplicateStamps rule);
DuplicateStamps parse_duplicate_stamps(const std::string& text);  // last, first, all

}  // namespace slamkit
