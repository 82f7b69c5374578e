#pragma once
// What the trajectory readers (TUM, KITTI, EuRoC) share: fields of a line, whole-field numbers,
// and the poses collected row by row before they are sorted and repeated stamps dropped, so
// that every format skips, warns and refuses by the same rules.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/line_reader.h"
#include "io/trajectory_io.h"

namespace slamkit {

// Splits on spaces, tabs, commas and CR, as the benchmark's read_file_list does; returns the
// number of fields (only the first `capacity` are stored).
size_t split_fields(std::string_view line, std::string_view* fields, size_t capacity);

// The whole field as a double (strtod's syntax without hex: an optional sign, inf, nan), or
// nullopt when any byte of it is not part of the number.
std::optional<double> parse_double(std::string_view text);

// A stamp in `unit` converted to seconds; integer stamps (the usual ns/us form) exactly.
std::optional<double> parse_stamp(std::string_view text, TimeUnit unit);

// An integer count of ticks (per_second a second) in seconds, exactly where a double can be.
double seconds_from_ticks(long long ticks, long long per_second);

// Field `index` (from 0) of line `line` as a number (a stamp in `unit` for index 0 when
// `unit` is given). InputError naming file and line when it is not wholly a number or is
// beyond kMaxTrajectoryValue.
double parse_field(std::string_view text, size_t index, const std::string& name, int line,
                   const TimeUnit* unit = nullptr);

// InputError naming the file when it is missing or a folder.
void require_file(const std::filesystem::path& path, const std::string& name);

// True for lines that hold no data: blank, '#' comments. Strips a UTF-8 byte order mark from
// line 1 first (as evo does).
bool skip_line(std::string_view& line, int number);

// Calls on_line(line, number) for each data line of the file at `path` (named `name` in
// messages), after checking it is a file. A template, not a std::function: it runs for each of
// up to millions of lines.
template <typename OnLine>
void for_each_data_line(const std::filesystem::path& path, const std::string& name,
                        OnLine&& on_line) {
  require_file(path, name);
  LineReader reader(path, name);
  std::string_view line;
  while (reader.next(line)) {
    const int number = reader.line_number();
    if (!skip_line(line, number)) on_line(line, number);
  }
}

// Poses in file order, with the line each came from.
class PoseRows {
 public:
  explicit PoseRows(std::string name) : name_(std::move(name)) {}

  // A line with a NaN or inf value: skipped with a warning, as the benchmark's reader does.
  void skip_non_finite(int line);
  // Adds a pose (any finite quaternion, normalised here); one with a non-finite value or a zero
  // quaternion is skipped with a warning. InputError beyond kMaxTrajectoryPoses.
  void add(double stamp, const Eigen::Vector3d& position, Eigen::Quaterniond q, int line);
  // Adds a pose given as a rotation matrix, kept as written (a reader adds all its rows one
  // way); one with a non-finite value is skipped with a warning.
  void add(double stamp, const Eigen::Vector3d& position, const Eigen::Matrix3d& R, int line);
  // Sorts (with a warning) if needed, keeps one pose of each repeated stamp. InputError when
  // no pose was added.
  TrajectoryFile finish(DuplicateStamps rule, const std::string& format);

 private:
  std::string name_;
  TrajectoryFile result_;
  std::vector<double> stamps_;
  std::vector<Eigen::Vector3d> positions_;
  std::vector<Eigen::Quaterniond> orientations_;       // rows added with a quaternion
  std::vector<Eigen::Matrix3d> rotations_as_written_;  // or with a matrix
  std::vector<int> lines_;

  void append(double stamp, const Eigen::Vector3d& position, int line);
  void sort_by_stamp();
  void drop_duplicates(DuplicateStamps rule);
};

}  // namespace slamkit
