#include "io/trajectory_format.h"

#include <stdexcept>

#include "core/enum_names.h"
#include "core/error.h"
#include "io/euroc_csv.h"
#include "io/kitti_poses.h"
#include "io/line_reader.h"
#include "io/pose_rows.h"

namespace slamkit {
namespace {

constexpr EnumNames<TrajectoryFormat, 3> kFormatNames = {{{TrajectoryFormat::kTum, "tum"},
                                                          {TrajectoryFormat::kKitti, "kitti"},
                                                          {TrajectoryFormat::kEuroc, "euroc"}}};

// Stamps beyond this are not seconds (eval refuses them as such): an integer this large is ns.
constexpr long long kLargestSecondsStamp = 100'000'000'000LL;

}  // namespace

std::string to_string(TrajectoryFormat format) { return name_of(kFormatNames, format); }

TrajectoryFormat parse_trajectory_format(const std::string& text) {
  if (const auto format = value_named(kFormatNames, text)) return *format;
  throw std::invalid_argument("unknown trajectory format '" + printable(text) + "' (use " +
                              choices(kFormatNames) + ")");
}

TrajectoryFormat detect_trajectory_format(const std::filesystem::path& path) {
  const std::string name = printable(path.string(), 4096);
  require_file(path, name);
  LineReader reader(path, name);
  std::string_view line;
  while (reader.next(line)) {
    const int number = reader.line_number();
    std::string_view text = line;
    if (number == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    // EuRoC's header: "#timestamp [ns],p_RS_R_x [m],..." (TUM's comments have no commas).
    if (text.substr(0, 10) == "#timestamp" && text.find(',') != std::string_view::npos)
      return TrajectoryFormat::kEuroc;
    if (skip_line(line, number)) continue;
    std::string_view first;
    const size_t count = split_fields(line, &first, 1);
    const bool commas = line.find(',') != std::string_view::npos;
    const auto ns = parse_nanoseconds(first);
    if (commas && count >= 8 && ns) {
      if (count > 8 && count != 12) return TrajectoryFormat::kEuroc;
      if (*ns > kLargestSecondsStamp || *ns < -kLargestSecondsStamp)
        return TrajectoryFormat::kEuroc;
      throw_input_error(name, number,
                        "cannot tell the format: " + std::to_string(count) +
                            " comma-separated fields with a small integer stamp fit " +
                            (count == 8 ? "tum and euroc" : "kitti and euroc") +
                            "; pass --format (or --gt-format / --est-format)");
    }
    // Anything else is read as TUM, the default, whose reader names the line it cannot read.
    return count == 12 ? TrajectoryFormat::kKitti : TrajectoryFormat::kTum;
  }
  return TrajectoryFormat::kTum;  // no data line: the TUM reader says "no valid pose"
}

TrajectoryFile read_trajectory(const std::filesystem::path& path,
                               std::optional<TrajectoryFormat> format,
                               const TrajectoryReadOptions& options,
                               const std::optional<std::filesystem::path>& kitti_times) {
  switch (format ? *format : detect_trajectory_format(path)) {
    case TrajectoryFormat::kKitti:
      return read_kitti_poses(path, kitti_times, options);
    case TrajectoryFormat::kEuroc:
      return read_euroc_csv(path, options);
    case TrajectoryFormat::kTum:
      break;
  }
  return read_tum_trajectory(path, options);
}

}  // namespace slamkit
