#include "eval/metrics/error_csv.h"

#include <charconv>
#include <fstream>
#include <string>

#include "core/error.h"

namespace slamkit::eval {
namespace {

std::ofstream open_csv(const std::filesystem::path& path, const char* header) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw_input_error(path.string(), "cannot write file");
  out << header << "\n";
  return out;
}

// Shortest text that reads back to the same double (format_exact's), so CSV values equal
// metrics.json's; appended to a line buffer (a string per number made large runs slow).
void put(std::string& line, double v, char sep = ',') {
  char text[400];  // fixed notation of the largest double needs 309 digits
  line.append(text, std::to_chars(text, text + sizeof text, v, std::chars_format::fixed).ptr);
  line += sep;
}

}  // namespace

void write_ate_csv(const std::filesystem::path& path, const AteResult& ate) {
  std::ofstream out = open_csv(path, "time,ate_m,est_tx,est_ty,est_tz,gt_tx,gt_ty,gt_tz,rot_deg");
  std::string line;
  for (size_t k = 0; k < ate.stamps.size(); ++k) {
    line.clear();
    put(line, ate.stamps[k]);
    put(line, ate.trans_errors[k]);
    for (int d = 0; d < 3; ++d) put(line, ate.est_aligned[k][d]);
    for (int d = 0; d < 3; ++d) put(line, ate.gt_positions[k][d]);
    put(line, ate.rot_errors_deg[k], '\n');
    out << line;
  }
  if (!out) throw_input_error(path.string(), "write failed");
}

void write_rpe_csv(const std::filesystem::path& path, const RpeResult& rpe) {
  std::ofstream out = open_csv(path, "time_i,time_j,gt_time_i,gt_time_j,trans_m,rot_deg");
  std::string line;
  for (const RpePair& p : rpe.pairs) {
    line.clear();
    put(line, p.stamp_est_i);
    put(line, p.stamp_est_j);
    put(line, p.stamp_gt_i);
    put(line, p.stamp_gt_j);
    put(line, p.trans);
    put(line, p.rot_deg, '\n');
    out << line;
  }
  if (!out) throw_input_error(path.string(), "write failed");
}

}  // namespace slamkit::eval
