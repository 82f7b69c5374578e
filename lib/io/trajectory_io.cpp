#include "io/trajectory_io.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include "core/enum_names.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/pose_rows.h"

namespace slamkit {

TrajectoryFile read_tum_trajectory(const std::filesystem::path& path,
                                   const TrajectoryReadOptions& options) {
  const std::string name = printable(path.string(), 4096);
  PoseRows rows(name);
  for_each_data_line(path, name, [&](std::string_view line, int number) {
    std::string_view fields[8];
    const size_t count = split_fields(line, fields, 8);
    if (count != 8)
      throw_input_error(
          name, number,
          "expected 8 fields 'timestamp tx ty tz qx qy qz qw', found " + std::to_string(count));
    double values[8];
    for (size_t k = 0; k < 8; ++k)
      values[k] = parse_field(fields[k], k, name, number, k == 0 ? &options.time_unit : nullptr);
    rows.add(values[0], Eigen::Vector3d(values[1], values[2], values[3]),
             Eigen::Quaterniond(values[7], values[4], values[5], values[6]), number);
  });
  return rows.finish(options.duplicates, "tum");
}

void write_tum_trajectory(const std::filesystem::path& path, const Trajectory& trajectory,
                          const std::string& header_comment) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  write_file_atomically(path, [&](std::ostream& out) {
    if (!header_comment.empty()) out << "# " << header_comment << "\n";
    out << "# timestamp tx ty tz qx qy qz qw\n";
    std::string line;
    char number[400];  // fixed notation of the largest double needs 309 digits
    const auto put = [&](double v, char separator) {
      line.append(number,
                  std::to_chars(number, number + sizeof number, v, std::chars_format::fixed).ptr);
      line += separator;
    };
    for (size_t i = 0; i < trajectory.size(); ++i) {
      // The stored quaternion, canonical (qw >= 0) as pose_to_tum writes it.
      Eigen::Quaterniond q = trajectory.orientation(i);
      if (q.w() < 0) q.coeffs() = -q.coeffs();
      const Eigen::Vector3d& t = trajectory.position(i);
      line.clear();
      put(trajectory.stamp(i), ' ');
      for (double v : {t.x(), t.y(), t.z(), q.x(), q.y(), q.z()}) put(v, ' ');
      put(q.w(), '\n');
      out << line;
    }
  });
}

std::string printable(std::string_view text, size_t max_length) {
  std::string out;
  const size_t n = std::min(text.size(), max_length);
  for (size_t k = 0; k < n; ++k) {
    const auto byte = static_cast<unsigned char>(text[k]);
    // C1 controls (U+0080..U+009F) are 0xC2 0x80..0x9F in UTF-8; some terminals obey them.
    const bool c1 = byte == 0xC2 && k + 1 < n && static_cast<unsigned char>(text[k + 1]) >= 0x80 &&
                    static_cast<unsigned char>(text[k + 1]) <= 0x9F;
    if (byte < 0x20 || byte == 0x7F || c1) {
      const unsigned code = c1 ? static_cast<unsigned char>(text[++k]) : byte;
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", code);
      out += escaped;
    } else {
      out += char(byte);
    }
  }
  if (text.size() > max_length) out += "...";
  return out;
}

namespace {
constexpr EnumNames<TimeUnit, 3> kTimeUnitNames = {
    {{TimeUnit::kSeconds, "s"}, {TimeUnit::kMicroseconds, "us"}, {TimeUnit::kNanoseconds, "ns"}}};
constexpr EnumNames<DuplicateStamps, 3> kDuplicateNames = {{{DuplicateStamps::kKeepLast, "last"},
                                                             {DuplicateStamps::kKeepFirst, "first"},
                                                             {DuplicateStamps::kKeepAll, "all"}}};
}  // namespace

std::string to_string(TimeUnit unit) { return name_of(kTimeUnitNames, unit); }

TimeUnit parse_time_unit(const std::string& text) {
  if (const auto unit = value_named(kTimeUnitNames, text)) return *unit;
  throw std::invalid_argument("unknown time unit '" + printable(text) + "' (use " +
                              choices(kTimeUnitNames) + ")");
}

std::string to_string(DuplicateStamps rule) { return name_of(kDuplicateNames, rule); }

DuplicateStamps parse_duplicate_stamps(const std::string& text) {
  if (const auto rule = value_named(kDuplicateNames, text)) return *rule;
  throw std::invalid_argument("unknown duplicate-stamp rule '" + printable(text) + "' (use " +
                              choices(kDuplicateNames) + ")");
}

}  // namespace slamkit
