#include "io/pose_rows.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "core/error.h"
#include "io/path_kind.h"

namespace slamkit {
namespace {

bool is_separator(char ch) { return ch == ' ' || ch == '\t' || ch == ',' || ch == '\r'; }

template <typename T>
void reorder(std::vector<T>& values, const std::vector<size_t>& order) {
  std::vector<T> out;
  out.reserve(order.size());
  for (size_t k : order) out.push_back(values[k]);
  values = std::move(out);
}

}  // namespace

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

std::optional<double> parse_stamp(std::string_view text, TimeUnit unit) {
  if (unit == TimeUnit::kSeconds) return parse_double(text);
  const long long per_second = unit == TimeUnit::kNanoseconds ? 1000000000LL : 1000000LL;
  long long ticks = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), ticks);
  if (error == std::errc() && end == text.data() + text.size())
    return seconds_from_ticks(ticks, per_second);
  const auto value = parse_double(text);
  if (!value) return std::nullopt;
  return *value / double(per_second);
}

double seconds_from_ticks(long long ticks, long long per_second) {
  return double(ticks / per_second) + double(ticks % per_second) / double(per_second);
}

double parse_field(std::string_view text, size_t index, const std::string& name, int line,
                   const TimeUnit* unit) {
  const auto value = unit ? parse_stamp(text, *unit) : parse_double(text);
  if (!value)
    throw_input_error(name, line,
                      "field " + std::to_string(index + 1) + " is not a number: '" +
                          printable(text) + "'");
  if (std::isfinite(*value) && std::abs(*value) > kMaxTrajectoryValue)
    throw_input_error(name, line,
                      "field " + std::to_string(index + 1) + " is " + printable(text) +
                          ", beyond +-1e100: not a plausible time or pose value (the "
                          "error statistics would overflow)");
  return *value;
}

void require_file(const std::filesystem::path& path, const std::string& name) {
  const PathKind kind = path_kind(path);
  if (kind == PathKind::kMissing) throw_input_error(name, "file not found");
  if (kind == PathKind::kFolder) throw_input_error(name, "is a folder, expected a file");
}

bool skip_line(std::string_view& line, int number) {
  if (number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);
  const size_t first = line.find_first_not_of(" \t\r");
  return first == std::string_view::npos || line[first] == '#';
}

void PoseRows::skip_non_finite(int line) {
  ++result_.non_finite_lines_skipped;
  result_.warnings.push_back(name_ + ":" + std::to_string(line) +
                             ": non-finite value, line skipped");
}

void PoseRows::add(double stamp, const Eigen::Vector3d& position, Eigen::Quaterniond q,
                   int line) {
  if (!std::isfinite(stamp) || !position.allFinite() || !q.coeffs().allFinite())
    return skip_non_finite(line);
  const double norm = q.norm();
  if (norm < 1e-12) {  // pose_from_tum's limit
    ++result_.zero_quaternions_skipped;
    result_.warnings.push_back(name_ + ":" + std::to_string(line) +
                               ": zero quaternion, line skipped");
    return;
  }
  q.coeffs() /= norm;
  append(stamp, position, line);
  orientations_.push_back(q);
}

void PoseRows::add(double stamp, const Eigen::Vector3d& position, const Eigen::Matrix3d& R,
                   int line) {
  if (!std::isfinite(stamp) || !position.allFinite() || !R.allFinite())
    return skip_non_finite(line);
  append(stamp, position, line);
  rotations_as_written_.push_back(R);
}

void PoseRows::append(double stamp, const Eigen::Vector3d& position, int line) {
  if (stamps_.size() == kMaxTrajectoryPoses)
    throw_input_error(name_, line,
                      "more than " + std::to_string(kMaxTrajectoryPoses) +
                          " poses: beyond what slamkit evaluates (cut the file, or subsample)");
  if (!stamps_.empty() && stamp < stamps_.back()) result_.was_unsorted = true;
  stamps_.push_back(stamp);
  positions_.push_back(position);
  lines_.push_back(line);
}

TrajectoryFile PoseRows::finish(DuplicateStamps rule, const std::string& format) {
  if (stamps_.empty()) throw_input_error(name_, "no valid pose in the file");
  if (result_.was_unsorted) {
    result_.warnings.push_back(name_ + ": timestamps are not in order; sorted them");
    sort_by_stamp();
  }
  drop_duplicates(rule);
  result_.format = format;
  result_.trajectory =
      rotations_as_written_.empty()
          ? Trajectory(std::move(stamps_), std::move(positions_), std::move(orientations_))
          : Trajectory(std::move(stamps_), std::move(positions_), std::move(rotations_as_written_));
  return std::move(result_);
}

// Reorders by time, stable (equal stamps keep their file order).
void PoseRows::sort_by_stamp() {
  std::vector<size_t> order(stamps_.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return stamps_[a] < stamps_[b]; });
  reorder(stamps_, order);
  reorder(positions_, order);
  if (!orientations_.empty()) reorder(orientations_, order);
  if (!rotations_as_written_.empty()) reorder(rotations_as_written_, order);
  reorder(lines_, order);
}

// Keeps one line of each run of equal stamps (in place), reporting each dropped line; with
// kKeepAll keeps them all, reporting each repeat.
void PoseRows::drop_duplicates(DuplicateStamps rule) {
  if (rule == DuplicateStamps::kKeepAll) {
    for (size_t k = 1; k < stamps_.size(); ++k)
      if (stamps_[k] == stamps_[k - 1])
        result_.warnings.push_back(name_ + ":" + std::to_string(lines_[k]) +
                                   ": duplicate timestamp, line kept beside line " +
                                   std::to_string(lines_[k - 1]));
    return;
  }
  size_t kept = 0;
  for (size_t begin = 0, end; begin < stamps_.size(); begin = end) {
    end = begin + 1;
    while (end < stamps_.size() && stamps_[end] == stamps_[begin]) ++end;
    const size_t keep = rule == DuplicateStamps::kKeepLast ? end - 1 : begin;
    for (size_t k = begin; k < end; ++k) {
      if (k == keep) continue;
      ++result_.duplicate_stamps_dropped;
      result_.warnings.push_back(name_ + ":" + std::to_string(lines_[k]) +
                                 (rule == DuplicateStamps::kKeepLast
                                      ? ": duplicate timestamp, line replaced by line "
                                      : ": duplicate timestamp, line dropped (keeping line ") +
                                 std::to_string(lines_[keep]) +
                                 (rule == DuplicateStamps::kKeepLast ? "" : ")"));
    }
    stamps_[kept] = stamps_[keep];
    positions_[kept] = positions_[keep];
    if (!orientations_.empty()) orientations_[kept] = orientations_[keep];
    if (!rotations_as_written_.empty()) rotations_as_written_[kept] = rotations_as_written_[keep];
    lines_[kept] = lines_[keep];
    ++kept;
  }
  stamps_.resize(kept);
  positions_.resize(kept);
  if (!orientations_.empty()) orientations_.resize(kept);
  if (!rotations_as_written_.empty()) rotations_as_written_.resize(kept);
  lines_.resize(kept);
}

}  // namespace slamkit
