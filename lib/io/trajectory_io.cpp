#include "io/trajectory_io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <numeric>
#include <optional>

#include "core/enum_names.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/line_reader.h"
#include "io/path_kind.h"

namespace slamkit {
namespace {

bool is_separator(char ch) { return ch == ' ' || ch == '\t' || ch == ',' || ch == '\r'; }

// Splits on spaces, tabs, commas and CR, as the benchmark's read_file_list does; returns the
// number of fields (only the first `capacity` are stored).
size_t split_fields(std::string_view line, std::string_view* fields, size_t capacity) {
  size_t count = 0, k = 0;
  while (k < line.size()) {
    while (k < line.size() && is_separator(line[k])) ++k;
    if (k == line.size()) break;
    const size_t start = k;
    while (k < line.size() && !is_separator(line[k])) ++k;
    if (count < capacity) fields[count] = line.substr(start, k - start);
    ++count;
  }
  return count;
}

// The whole field as a double (strtod's syntax without hex: an optional sign, inf, nan), or
// nullopt when any byte of it is not part of the number.
std::optional<double> parse_double(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    // from_chars refuses out-of-range values (1e999, 1e-999) where strtod gives inf or 0.
    if (error == std::errc::result_out_of_range && end == text.data() + text.size())
      return std::strtod(std::string(text).c_str(), nullptr);
    return std::nullopt;
  }
  return value;
}

// A stamp in `unit` converted to seconds; integer stamps (the usual ns/us form) exactly.
std::optional<double> parse_stamp(std::string_view text, TimeUnit unit) {
  if (unit == TimeUnit::kSeconds) return parse_double(text);
  const long long per_second = unit == TimeUnit::kNanoseconds ? 1000000000LL : 1000000LL;
  long long ticks = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), ticks);
  if (error == std::errc() && end == text.data() + text.size())
    return double(ticks / per_second) + double(ticks % per_second) / double(per_second);
  const auto value = parse_double(text);
  if (!value) return std::nullopt;
  return *value / double(per_second);
}

struct Parsed {
  std::vector<double> stamps;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Quaterniond> orientations;
  std::vector<int> lines;

  void push_back(double stamp, const Eigen::Vector3d& p, const Eigen::Quaterniond& q, int line) {
    stamps.push_back(stamp);
    positions.push_back(p);
    orientations.push_back(q);
    lines.push_back(line);
  }
};

// Reorders by time, stable (equal stamps keep their file order).
void sort_by_stamp(Parsed& in) {
  std::vector<size_t> order(in.stamps.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return in.stamps[a] < in.stamps[b]; });
  Parsed out;
  for (size_t k : order)
    out.push_back(in.stamps[k], in.positions[k], in.orientations[k], in.lines[k]);
  in = std::move(out);
}

// Keeps one line of each run of equal stamps (in place), reporting each dropped line.
void drop_duplicates(Parsed& p, DuplicateStamps rule, const std::string& name,
                     TrajectoryFile& result) {
  size_t kept = 0;
  for (size_t begin = 0, end; begin < p.stamps.size(); begin = end) {
    end = begin + 1;
    while (end < p.stamps.size() && p.stamps[end] == p.stamps[begin]) ++end;
    const size_t keep = rule == DuplicateStamps::kKeepLast ? end - 1 : begin;
    for (size_t k = begin; k < end; ++k) {
      if (k == keep) continue;
      ++result.duplicate_stamps_dropped;
      result.warnings.push_back(name + ":" + std::to_string(p.lines[k]) +
                                (rule == DuplicateStamps::kKeepLast
                                     ? ": duplicate timestamp, line replaced by line "
                                     : ": duplicate timestamp, line dropped (keeping line ") +
                                std::to_string(p.lines[keep]) +
                                (rule == DuplicateStamps::kKeepLast ? "" : ")"));
    }
    p.stamps[kept] = p.stamps[keep];
    p.positions[kept] = p.positions[keep];
    p.orientations[kept] = p.orientations[keep];
    p.lines[kept] = p.lines[keep];
    ++kept;
  }
  p.stamps.resize(kept);
  p.positions.resize(kept);
  p.orientations.resize(kept);
  p.lines.resize(kept);
}

}  // namespace

TrajectoryFile read_tum_trajectory(const std::filesystem::path& path,
                                   const TrajectoryReadOptions& options) {
  const std::string name = printable(path.string(), 4096);
  const PathKind kind = path_kind(path);
  if (kind == PathKind::kMissing) throw_input_error(name, "file not found");
  if (kind == PathKind::kFolder) throw_input_error(name, "is a folder, expected a file");
  LineReader reader(path, name);

  TrajectoryFile result;
  Parsed parsed;
  std::string_view line;
  while (reader.next(line)) {
    const int number = reader.line_number();
    if (number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // BOM
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    std::string_view fields[8];
    const size_t count = split_fields(line, fields, 8);
    if (count != 8)
      throw_input_error(
          name, number,
          "expected 8 fields 'timestamp tx ty tz qx qy qz qw', found " + std::to_string(count));
    double values[8];
    for (size_t k = 0; k < 8; ++k) {
      const auto value =
          k == 0 ? parse_stamp(fields[k], options.time_unit) : parse_double(fields[k]);
      if (!value)
        throw_input_error(
            name, number,
            "field " + std::to_string(k + 1) + " is not a number: '" + printable(fields[k]) + "'");
      if (std::isfinite(*value) && std::abs(*value) > kMaxTrajectoryValue)
        throw_input_error(name, number,
                          "field " + std::to_string(k + 1) + " is " + printable(fields[k]) +
                              ", beyond +-1e100: not a plausible time or pose value (the "
                              "error statistics would overflow)");
      values[k] = *value;
    }
    if (!std::all_of(values, values + 8, [](double v) { return std::isfinite(v); })) {
      ++result.non_finite_lines_skipped;
      result.warnings.push_back(name + ":" + std::to_string(number) +
                                ": non-finite value, line skipped");
      continue;
    }
    Eigen::Quaterniond q(values[7], values[4], values[5], values[6]);
    const double norm = q.norm();
    if (norm < 1e-12) {  // pose_from_tum's limit
      ++result.zero_quaternions_skipped;
      result.warnings.push_back(name + ":" + std::to_string(number) +
                                ": zero quaternion, line skipped");
      continue;
    }
    q.coeffs() /= norm;
    if (parsed.stamps.size() == kMaxTrajectoryPoses)
      throw_input_error(name, number,
                        "more than " + std::to_string(kMaxTrajectoryPoses) +
                            " poses: beyond what slamkit evaluates (cut the file, or subsample)");
    if (!parsed.stamps.empty() && values[0] < parsed.stamps.back()) result.was_unsorted = true;
    parsed.push_back(values[0], Eigen::Vector3d(values[1], values[2], values[3]), q, number);
  }
  if (parsed.stamps.empty()) throw_input_error(name, "no valid pose in the file");
  if (result.was_unsorted) {
    result.warnings.push_back(name + ": timestamps are not in order; sorted them");
    sort_by_stamp(parsed);
  }
  drop_duplicates(parsed, options.duplicates, name, result);
  result.trajectory = Trajectory(std::move(parsed.stamps), std::move(parsed.positions),
                                 std::move(parsed.orientations));
  return result;
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
constexpr EnumNames<DuplicateStamps, 2> kDuplicateNames = {
    {{DuplicateStamps::kKeepLast, "last"}, {DuplicateStamps::kKeepFirst, "first"}}};
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
