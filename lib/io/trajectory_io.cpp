#include "io/trajectory_io.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"
#include "core/number_format.h"
#include "core/pose.h"
#include "io/text_table.h"

namespace slamkit {

TrajectoryFile read_tum_trajectory(const std::filesystem::path& path) {
  const std::string name = path.string();
  TrajectoryFile result;
  std::vector<StampedPose> poses;
  std::vector<int> lines;
  for (const TableRow& row : read_table(path)) {
    if (row.fields.size() != 8)
      throw_input_error(name, row.line,
                        "expected 8 fields 'timestamp tx ty tz qx qy qz qw', found " +
                            std::to_string(row.fields.size()));
    const double stamp = parse_number(path, row, 0);
    std::array<double, 7> values;
    for (size_t k = 0; k < 7; ++k) values[k] = parse_number(path, row, k + 1);
    const bool finite = std::isfinite(stamp) && std::all_of(values.begin(), values.end(),
                                                            [](double v) { return std::isfinite(v); });
    if (!finite) {
      ++result.non_finite_lines_skipped;
      result.warnings.push_back(name + ":" + std::to_string(row.line) +
                                ": non-finite value, line skipped");
      continue;
    }
    const auto T = pose_from_tum(values);
    if (!T) {
      ++result.zero_quaternions_skipped;
      result.warnings.push_back(name + ":" + std::to_string(row.line) +
                                ": zero quaternion, line skipped");
      continue;
    }
    if (!poses.empty() && stamp < poses.back().stamp) result.was_unsorted = true;
    poses.push_back({stamp, *T});
    lines.push_back(row.line);
  }
  if (poses.empty()) throw_input_error(name, "no valid pose in the file");
  if (result.was_unsorted)
    result.warnings.push_back(name + ": timestamps are not in order; sorted them");

  // Duplicate stamps: the later line wins, as in the benchmark's dict-based reader.
  std::vector<size_t> order(poses.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return poses[a].stamp < poses[b].stamp; });
  std::vector<StampedPose> unique;
  for (size_t k = 0; k < order.size(); ++k) {
    const bool duplicate = k + 1 < order.size() && poses[order[k + 1]].stamp == poses[order[k]].stamp;
    if (!duplicate) {
      unique.push_back(poses[order[k]]);
      continue;
    }
    ++result.duplicate_stamps_dropped;
    result.warnings.push_back(name + ":" + std::to_string(lines[order[k]]) +
                              ": duplicate timestamp, line replaced by line " +
                              std::to_string(lines[order[k + 1]]));
  }
  poses = std::move(unique);
  result.trajectory = Trajectory(std::move(poses));
  return result;
}

void write_tum_trajectory(const std::filesystem::path& path, const Trajectory& trajectory,
                          const std::string& header_comment) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw_input_error(path.string(), "cannot write file");
  if (!header_comment.empty()) out << "# " << header_comment << "\n";
  out << "# timestamp tx ty tz qx qy qz qw\n";
  for (const StampedPose& p : trajectory.poses()) {
    out << format_exact(p.stamp);
    for (double v : pose_to_tum(p.T_w_c)) out << ' ' << format_exact(v);
    out << '\n';
  }
  if (!out.flush()) throw_input_error(path.string(), "write failed");
}

}  // namespace slamkit
