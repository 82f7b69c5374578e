#include "eval/metrics/summary.h"

#include <cstdarg>
#include <cstdio>

#include "eval/metrics/metrics_json.h"

namespace slamkit::eval {
namespace {

void append(std::string& out, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void append(std::string& out, const char* fmt, ...) {
  char line[256];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(line, sizeof line, fmt, args);
  va_end(args);
  out += line;
}

void append_stats(std::string& out, const char* prefix, const ErrorStats& s, const char* unit) {
  append(out, "%s.rmse %f %s\n", prefix, s.rmse, unit);
  append(out, "%s.mean %f %s\n", prefix, s.mean, unit);
  append(out, "%s.median %f %s\n", prefix, s.median, unit);
  append(out, "%s.std %f %s\n", prefix, s.std, unit);
  append(out, "%s.min %f %s\n", prefix, s.min, unit);
  append(out, "%s.max %f %s\n", prefix, s.max, unit);
}

}  // namespace

std::string ate_summary(const AteResult& ate, const Coverage& c) {
  std::string out;
  append(out,
         "compared_pose_pairs %zu pairs (of %zu estimated poses; overlap %.1f%% of "
         "groundtruth time span)\n",
         ate.trans.count, c.est_poses, 100.0 * c.fraction_of_gt);
  const Alignment& a = ate.alignment;
  append(out, "alignment %s on %zu pairs, scale %f\n", to_string(a.method).c_str(), a.poses_used,
         a.scale);
  append_stats(out, "absolute_translational_error", ate.trans, "m");
  if (a.rotation_well_determined()) {
    append_stats(out, "absolute_rotational_error", ate.rot_deg, "deg");
  } else {
    out += "absolute_rotational_error withheld: " + rotation_withheld_reason(a) + "\n";
  }
  return out;
}

std::string rpe_summary(const RpeResult& rpe, const RpeOptions& o) {
  std::string out;
  append(out, "compared_pose_pairs %zu pairs (delta %g %s%s, %s convention", rpe.pairs.size(),
         o.delta, to_string(o.unit).c_str(), o.all_pairs ? ", all pairs" : "",
         to_string(o.convention).c_str());
  if (o.scale != 1.0) append(out, ", estimate scaled by %f", o.scale);
  out += ")\n";
  append_stats(out, "translational_error", rpe.trans, "m");
  append_stats(out, "rotational_error", rpe.rot_deg, "deg");
  return out;
}

std::string kitti_summary(const KittiOdometryResult& kitti, size_t pairs) {
  std::string out;
  append(out, "kitti_segments %zu (of %zu frames; 100..800 m from every 10th frame)\n",
         kitti.segments.size(), pairs);
  append(out, "kitti.translational_error %f %%\n", kitti.trans_pct);
  append(out, "kitti.rotational_error %f deg/m\n", kitti.rot_deg_per_m);
  for (const KittiLengthError& l : kitti.lengths)
    append(out, "kitti.%gm %f %% %f deg/m (%zu segments)\n", l.length_m, l.trans_pct,
           l.rot_deg_per_m, l.segments);
  return out;
}

}  // namespace slamkit::eval
