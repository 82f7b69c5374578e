#include "io/kitti_poses.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "core/number_format.h"
#include "io/atomic_file.h"
#include "io/pose_rows.h"

namespace slamkit {
namespace {

// A row-major 3x3 block further from a rotation than printf's 6 digits can explain is not one.
constexpr double kRotationTolerance = 1e-3;

struct Stamps {
  std::vector<double> values;
  std::vector<int> lines;
};

Stamps read_times(const std::filesystem::path& path, const TimeUnit unit) {
  const std::string name = printable(path.string(), 4096);
  Stamps stamps;
  for_each_data_line(path, name, [&](std::string_view line, int number) {
    std::string_view field;
    const size_t count = split_fields(line, &field, 1);
    if (count != 1)
      throw_input_error(name, number,
                        "expected 1 field (a time in seconds), found " + std::to_string(count));
    if (stamps.values.size() == kMaxTrajectoryPoses)
      throw_input_error(name, number,
                        "more than " + std::to_string(kMaxTrajectoryPoses) + " stamps");
    stamps.values.push_back(parse_field(field, 0, name, number, &unit));
    stamps.lines.push_back(number);
  });
  return stamps;
}

// How far the block is from a rotation, or a message saying why it is not one.
std::string rotation_problem(const Eigen::Matrix3d& R) {
  const double off = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (off > kRotationTolerance)
    return "fields 1-3, 5-7, 9-11 are not a rotation matrix (|R^T R - I| = " +
           std::to_string(off) + ")";
  if (R.determinant() < 0) return "fields 1-3, 5-7, 9-11 are a reflection (det R < 0)";
  return "";
}

}  // namespace

TrajectoryFile read_kitti_poses(const std::filesystem::path& path,
                                const std::optional<std::filesystem::path>& times,
                                const TrajectoryReadOptions& options) {
  const Stamps stamps = times ? read_times(*times, options.time_unit) : Stamps{};
  const std::string times_name = times ? printable(times->string(), 4096) : "";
  const std::string name = printable(path.string(), 4096);
  PoseRows rows(name);
  size_t index = 0;  // of the pose line, which its stamp shares
  for_each_data_line(path, name, [&](std::string_view line, int number) {
    std::string_view fields[12];
    const size_t count = split_fields(line, fields, 12);
    if (count != 12)
      throw_input_error(name, number,
                        "expected 12 fields (the row-major 3x4 matrix [R|t]), found " +
                            std::to_string(count));
    double v[12];
    for (size_t k = 0; k < 12; ++k) v[k] = parse_field(fields[k], k, name, number);
    if (times && index == stamps.values.size())
      throw_input_error(name, number,
                        "pose " + std::to_string(index + 1) + " has no stamp: " + times_name +
                            " holds " + std::to_string(stamps.values.size()) + " stamps");
    const double stamp = times ? stamps.values[index] : double(index);
    ++index;
    if (!std::all_of(v, v + 12, [](double x) { return std::isfinite(x); }) ||
        !std::isfinite(stamp)) {
      rows.skip_non_finite(number);
      return;
    }
    Eigen::Matrix3d R;
    R << v[0], v[1], v[2], v[4], v[5], v[6], v[8], v[9], v[10];
    if (const std::string problem = rotation_problem(R); !problem.empty())
      throw_input_error(name, number, problem);
    rows.add(stamp, Eigen::Vector3d(v[3], v[7], v[11]), R, number);
  });
  if (times && index < stamps.values.size())
    throw_input_error(times_name, stamps.lines[index],
                      "stamp " + std::to_string(index + 1) + " has no pose: " + name +
                          " holds " + std::to_string(index) + " poses");
  return rows.finish(options.duplicates, "kitti");
}

void write_kitti_poses(const std::filesystem::path& path, const Trajectory& trajectory,
                       const std::optional<std::filesystem::path>& times) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  write_file_atomically(path, [&](std::ostream& out) {
    for (size_t i = 0; i < trajectory.size(); ++i) {
      const Eigen::Matrix3d R = trajectory.pose(i).linear();
      const Eigen::Vector3d& t = trajectory.position(i);
      for (int r = 0; r < 3; ++r)
        out << format_exact(R(r, 0)) << ' ' << format_exact(R(r, 1)) << ' '
            << format_exact(R(r, 2)) << ' ' << format_exact(t(r)) << (r < 2 ? ' ' : '\n');
    }
  });
  if (!times) return;
  if (times->has_parent_path()) std::filesystem::create_directories(times->parent_path());
  write_file_atomically(*times, [&](std::ostream& out) {
    for (size_t i = 0; i < trajectory.size(); ++i) out << format_exact(trajectory.stamp(i)) << '\n';
  });
}

}  // namespace slamkit
