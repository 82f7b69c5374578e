#include "eval/rpe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/enum_names.h"
#include "core/error.h"
#include "core/pose.h"
#include "eval/statistics.h"

namespace slamkit::eval {
namespace {

using Poses = std::vector<Eigen::Isometry3d>;

double rad_to_deg(double rad) { return rad * 180.0 / M_PI; }

// compute_angle() of evaluate_rpe.py, kept as is (not the more robust log) so that the
// benchmark's numbers come out to the last digit.
double trace_angle(const Eigen::Matrix3d& R) {
  return std::acos(std::min(1.0, std::max(-1.0, (R.trace() - 1.0) / 2.0)));
}

// The delta "index" of every pose: time, frame number, path length or accumulated rotation
// (the script's distances_along_trajectory / rotations_along_trajectory).
std::vector<double> delta_index(const std::vector<double>& stamps, const Poses& poses,
                                DeltaUnit unit) {
  std::vector<double> index(poses.size(), 0.0);
  for (size_t k = 1; k < poses.size(); ++k) {
    const Eigen::Isometry3d motion = poses[k].inverse() * poses[k - 1];
    switch (unit) {
      case DeltaUnit::kSeconds:
        index[k] = stamps[k];
        break;
      case DeltaUnit::kFrames:
        index[k] = double(k);
        break;
      case DeltaUnit::kMetres:
        index[k] = index[k - 1] + motion.translation().norm();
        break;
      case DeltaUnit::kDegrees:
        index[k] = index[k - 1] + rad_to_deg(trace_angle(motion.rotation()));
        break;
    }
  }
  if (unit == DeltaUnit::kSeconds && !stamps.empty()) index[0] = stamps[0];
  return index;
}

// Pairs (i, j) with index_j closest to index_i + delta; `drop_last` is the script's
// `if j != len(traj_est)-1`.
std::vector<std::pair<size_t, size_t>> closest_delta_pairs(const std::vector<double>& index,
                                                           double delta, bool drop_last) {
  std::vector<std::pair<size_t, size_t>> pairs;
  for (size_t i = 0; i < index.size(); ++i) {
    const size_t j = find_closest_index(index, index[i] + delta);
    if (drop_last && j == index.size() - 1) continue;
    pairs.push_back({i, j});
  }
  return pairs;
}

// evo's filters.id_pairs_from_delta on the associated poses.
std::vector<std::pair<size_t, size_t>> evo_pairs(const std::vector<double>& stamps,
                                                 const Poses& poses, const RpeOptions& o) {
  std::vector<std::pair<size_t, size_t>> pairs;
  const size_t n = poses.size();
  if (o.unit == DeltaUnit::kFrames) {  // filter_pairs_by_index
    const size_t d = size_t(std::llround(o.delta));
    if (d == 0) throw std::invalid_argument("--delta must be at least 1 frame");
    if (o.all_pairs) {
      for (size_t i = 0; i + d < n; ++i) pairs.push_back({i, i + d});
    } else {
      for (size_t i = 0; i + d < n; i += d) pairs.push_back({i, i + d});
    }
    return pairs;
  }
  if (o.unit == DeltaUnit::kMetres && !o.all_pairs) {  // filter_pairs_by_path, consecutive
    std::vector<size_t> ids;
    double path = 0;
    for (size_t k = 1; k < n; ++k) {
      path += (poses[k].translation() - poses[k - 1].translation()).norm();
      if (path >= o.delta) {
        ids.push_back(k);
        path = 0;
      }
    }
    for (size_t k = 1; k < ids.size(); ++k) pairs.push_back({ids[k - 1], ids[k]});
    return pairs;
  }
  // Seconds (evo has no time delta), degrees and all-pairs metres: the benchmark's
  // closest-index rule, keeping the last pose like evo does. See eval/README.md.
  return closest_delta_pairs(delta_index(stamps, poses, o.unit), o.delta, false);
}

RpeResult finish(std::vector<RpePair> pairs, const std::string& est_name, size_t candidates) {
  if (pairs.size() < 2) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "RPE found %zu valid pose pair(s) (of %zu candidates) with groundtruth "
                  "nearby; need at least 2: is delta longer than the trajectory, or does "
                  "groundtruth not cover it?",
                  pairs.size(), candidates);
    throw_input_error(est_name, text);
  }
  RpeResult r;
  std::vector<double> trans, rot;
  for (const RpePair& p : pairs) {
    trans.push_back(p.trans);
    rot.push_back(p.rot_deg);
  }
  r.pairs = std::move(pairs);
  r.trans = compute_stats(trans);
  r.rot_deg = compute_stats(rot);
  return r;
}

RpeResult rpe_tum(const Trajectory& gt, const Trajectory& est, const RpeOptions& o,
                  const std::string& est_name) {
  const std::vector<double> stamps_est = est.stamps(), stamps_gt = gt.stamps();
  Poses poses(est.size());
  for (size_t k = 0; k < est.size(); ++k) poses[k] = est[k].T_w_c;

  std::vector<std::pair<size_t, size_t>> pairs;
  if (o.all_pairs) {
    for (size_t i = 0; i < est.size(); ++i)
      for (size_t j = i + 1; j < est.size(); ++j) pairs.push_back({i, j});
  } else {
    pairs = closest_delta_pairs(delta_index(stamps_est, poses, o.unit), o.delta, true);
  }

  std::vector<double> intervals;
  for (size_t k = 1; k < stamps_gt.size(); ++k)
    intervals.push_back(stamps_gt[k] - stamps_gt[k - 1]);
  const double max_time_diff = 2.0 * compute_stats(intervals).median;

  // Nearest groundtruth pose of each estimated pose, or none if too far (computed once).
  std::vector<long> gt_of(est.size(), -1);
  for (size_t k = 0; k < est.size(); ++k) {
    const double t = stamps_est[k] + o.offset;
    const size_t g = find_closest_index(stamps_gt, t);
    if (!(std::abs(stamps_gt[g] - t) > max_time_diff)) gt_of[k] = long(g);
  }

  std::vector<RpePair> out;
  for (const auto& [i, j] : pairs) {
    if (gt_of[i] < 0 || gt_of[j] < 0) continue;
    const StampedPose& q_i = gt[size_t(gt_of[i])];
    const StampedPose& q_j = gt[size_t(gt_of[j])];
    // error44 = ominus(ominus(P_j, P_i), ominus(Q_j, Q_i)) with ominus(a, b) = a^-1 b.
    const Eigen::Isometry3d E =
        (poses[j].inverse() * poses[i]).inverse() * (q_j.T_w_c.inverse() * q_i.T_w_c);
    out.push_back({stamps_est[i], stamps_est[j], q_i.stamp, q_j.stamp, E.translation().norm(),
                   rad_to_deg(trace_angle(E.rotation()))});
  }
  return finish(std::move(out), est_name, pairs.size());
}

RpeResult rpe_evo(const Trajectory& gt, const Trajectory& est,
                  const std::vector<IndexPair>& associated, const RpeOptions& o,
                  const std::string& est_name) {
  std::vector<double> stamps;
  Poses P, Q;
  for (const IndexPair& a : associated) {
    stamps.push_back(est[a.second].stamp);
    P.push_back(est[a.second].T_w_c);
    Q.push_back(gt[a.first].T_w_c);
  }
  std::vector<std::pair<size_t, size_t>> pairs;
  if (!P.empty()) pairs = evo_pairs(stamps, P, o);
  std::vector<RpePair> out;
  for (const auto& [i, j] : pairs) {
    // evo's rpe_base: E = relative(Q_rel, P_rel), relative(a, b) = a^-1 b.
    const Eigen::Isometry3d E = (Q[i].inverse() * Q[j]).inverse() * (P[i].inverse() * P[j]);
    out.push_back({stamps[i], stamps[j], gt[associated[i].first].stamp,
                   gt[associated[j].first].stamp, E.translation().norm(),
                   rad_to_deg(rotation_angle(E))});
  }
  return finish(std::move(out), est_name, pairs.size());
}

}  // namespace

size_t find_closest_index(const std::vector<double>& L, double t) {
  // Hand-written port of evaluate_rpe.py's find_closest_index rather than std::lower_bound:
  // its tie-breaking decides which pose is j when two are equally close.
  size_t begin = 0, end = L.size(), best = 0;
  double difference = std::abs(L[0] - t);
  while (begin < end) {
    const size_t middle = (begin + end) / 2;
    if (std::abs(L[middle] - t) < difference) {
      difference = std::abs(L[middle] - t);
      best = middle;
    }
    if (t == L[middle]) return middle;
    if (L[middle] > t) {
      end = middle;
    } else {
      begin = middle + 1;
    }
  }
  return best;
}

RpeResult compute_rpe(const Trajectory& gt, const Trajectory& est,
                      const std::vector<IndexPair>& associated, const RpeOptions& options,
                      const std::string& est_name) {
  if (!(options.delta > 0) && !options.all_pairs)
    throw std::invalid_argument("--delta must be positive");
  return options.convention == RpeConvention::kTum
             ? rpe_tum(gt, est, options, est_name)
             : rpe_evo(gt, est, associated, options, est_name);
}

namespace {
constexpr EnumNames<DeltaUnit, 4> kDeltaUnitNames = {{{DeltaUnit::kSeconds, "s"},
                                                      {DeltaUnit::kFrames, "f"},
                                                      {DeltaUnit::kMetres, "m"},
                                                      {DeltaUnit::kDegrees, "deg"}}};
constexpr EnumNames<RpeConvention, 2> kConventionNames = {
    {{RpeConvention::kTum, "tum"}, {RpeConvention::kEvo, "evo"}}};
}  // namespace

std::string to_string(DeltaUnit unit) { return name_of(kDeltaUnitNames, unit); }

DeltaUnit parse_delta_unit(const std::string& text) {
  if (const auto unit = value_named(kDeltaUnitNames, text)) return *unit;
  throw std::invalid_argument("unknown delta unit '" + text + "' (use " +
                              choices(kDeltaUnitNames) + ")");
}

std::string to_string(RpeConvention convention) { return name_of(kConventionNames, convention); }

RpeConvention parse_rpe_convention(const std::string& text) {
  if (const auto convention = value_named(kConventionNames, text)) return *convention;
  throw std::invalid_argument("unknown RPE convention '" + text + "' (use " +
                              choices(kConventionNames) + ")");
}

}  // namespace slamkit::eval
