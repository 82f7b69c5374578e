#include "eval/error_csv.h"

#include <fstream>
#include <string>

#include "core/error.h"
#include "core/number_format.h"

namespace slamkit::eval {
namespace {

std::ofstream open_csv(const std::filesystem::path& path, const char* header) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw_input_error(path.string(), "cannot write file");
  out << header << "\n";
  return out;
}

// Shortest text that reads back to the same double, so CSV values equal metrics.json's.
void put(std::ofstream& out, double v, char sep = ',') { out << format_exact(v) << sep; }

}  // namespace

void write_ate_csv(const std::filesystem::path& path, const AteResult& ate) {
  std::ofstream out = open_csv(path, "time,ate_m,est_tx,est_ty,est_tz,gt_tx,gt_ty,gt_tz,rot_deg");
  for (size_t k = 0; k < ate.stamps.size(); ++k) {
    put(out, ate.stamps[k]);
    put(out, ate.trans_errors[k]);
    for (int d = 0; d < 3; ++d) put(out, ate.est_aligned[k][d]);
    for (int d = 0; d < 3; ++d) put(out, ate.gt_positions[k][d]);
    put(out, ate.rot_errors_deg[k], '\n');
  }
  if (!out) throw_input_error(path.string(), "write failed");
}

void write_rpe_csv(const std::filesystem::path& path, const RpeResult& rpe) {
  std::ofstream out = open_csv(path, "time_i,time_j,gt_time_i,gt_time_j,trans_m,rot_deg");
  for (const RpePair& p : rpe.pairs) {
    put(out, p.stamp_est_i);
    put(out, p.stamp_est_j);
    put(out, p.stamp_gt_i);
    put(out, p.stamp_gt_j);
    put(out, p.trans);
    put(out, p.rot_deg, '\n');
  }
  if (!out) throw_input_error(path.string(), "write failed");
}

}  // namespace slamkit::eval
