#include "io/euroc_csv.h"

#include <charconv>
#include <cmath>

#include "core/error.h"
#include "core/number_format.h"
#include "io/atomic_file.h"
#include "io/pose_rows.h"

namespace slamkit {

std::optional<long long> parse_nanoseconds(std::string_view text, bool* overflow) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  long long ns = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), ns);
  const bool whole = end == text.data() + text.size() && !text.empty();
  if (overflow) *overflow = whole && error == std::errc::result_out_of_range;
  if (error != std::errc() || !whole) return std::nullopt;
  return ns;
}

TrajectoryFile read_euroc_csv(const std::filesystem::path& path,
                              const TrajectoryReadOptions& options) {
  const std::string name = printable(path.string(), 4096);
  PoseRows rows(name);
  for_each_data_line(path, name, [&](std::string_view line, int number) {
    std::string_view fields[8];
    const size_t count = split_fields(line, fields, 8);
    if (count < 8)
      throw_input_error(name, number,
                        "expected at least 8 fields 'timestamp [ns], p_x, p_y, p_z, q_w, q_x, "
                        "q_y, q_z', found " +
                            std::to_string(count));
    bool overflow = false;
    const auto ns = parse_nanoseconds(fields[0], &overflow);
    if (!ns)
      throw_input_error(name, number,
                        "field 1 is " + std::string(overflow ? "beyond int64" : "not an integer") +
                            ": '" + printable(fields[0]) +
                            "' (EuRoC stamps are integer nanoseconds)");
    double v[8];
    for (size_t k = 1; k < 8; ++k) v[k] = parse_field(fields[k], k, name, number);
    rows.add(seconds_from_ticks(*ns, 1000000000LL), Eigen::Vector3d(v[1], v[2], v[3]),
             Eigen::Quaterniond(v[4], v[5], v[6], v[7]), number);  // w first
  });
  return rows.finish(options.duplicates, "euroc");
}

void write_euroc_csv(const std::filesystem::path& path, const Trajectory& trajectory) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  constexpr long long kPerSecond = 1000000000;
  write_file_atomically(path, [&](std::ostream& out) {
    out << "#timestamp [ns],p_RS_R_x [m],p_RS_R_y [m],p_RS_R_z [m],q_RS_w [],q_RS_x [],q_RS_y [],"
           "q_RS_z []\n";
    for (size_t i = 0; i < trajectory.size(); ++i) {
      // Whole seconds and the fraction apart, as seconds_from_ticks reads them: the fraction is
      // exact, so the nanoseconds are the nearest ones and read back to the same double.
      const double stamp = trajectory.stamp(i);
      const double whole = std::floor(stamp);
      if (!(std::abs(whole) < 9.2e9))
        throw_input_error(path.string(), "stamp " + format_exact(stamp) +
                                             " s is beyond int64 nanoseconds (about 292 years)");
      const long long ns = (long long)(whole)*kPerSecond + std::llround((stamp - whole) * 1e9);
      Eigen::Quaterniond q = trajectory.orientation(i);
      if (q.w() < 0) q.coeffs() = -q.coeffs();
      const Eigen::Vector3d& t = trajectory.position(i);
      out << ns;
      for (double v : {t.x(), t.y(), t.z(), q.w(), q.x(), q.y(), q.z()}) out << ',' << format_exact(v);
      out << '\n';
    }
  });
}

}  // namespace slamkit
