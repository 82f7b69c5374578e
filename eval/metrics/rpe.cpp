#include "eval/metrics/rpe.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "core/enum_names.h"
#include "core/error.h"
#include "core/pose.h"
#include "eval/metrics/statistics.h"

namespace slamkit::eval {
namespace {

using IdPairs = std::vector<std::pair<size_t, size_t>>;

double rad_to_deg(double rad) { return rad * 180.0 / M_PI; }

// compute_angle() of evaluate_rpe.py, kept as is (not the more robust log) so that the
// benchmark's numbers come out to the last digit.
double trace_angle(const Eigen::Matrix3d& R) {
  return std::acos(std::min(1.0, std::max(-1.0, (R.trace() - 1.0) / 2.0)));
}

// Pose k of a pose list, rebuilt on demand (a million poses as matrices would take 128 MB).
using PoseAt = std::function<Eigen::Isometry3d(size_t)>;

// The estimated pose with its position scaled (see RpeOptions::scale); unchanged at scale 1.
Eigen::Isometry3d scaled(Eigen::Isometry3d T, double scale) {
  if (scale != 1.0) T.translation() *= scale;
  return T;
}

// The delta "index" of every pose for frames, metres, degrees and radians (seconds use the
// stamps): frame number, path length or accumulated rotation (the script's
// distances_along_trajectory / rotations_along_trajectory).
std::vector<double> delta_index(const std::vector<double>& stamps, const PoseAt& pose,
                                DeltaUnit unit) {
  std::vector<double> index(stamps.size(), 0.0);
  if (unit == DeltaUnit::kFrames) {
    std::iota(index.begin(), index.end(), 0.0);
    return index;
  }
  Eigen::Isometry3d previous = stamps.empty() ? Eigen::Isometry3d::Identity() : pose(0);
  for (size_t k = 1; k < stamps.size(); ++k) {
    const Eigen::Isometry3d current = pose(k);
    const Eigen::Isometry3d motion = current.inverse() * previous;
    const double angle = trace_angle(motion.rotation());
    index[k] = index[k - 1] + (unit == DeltaUnit::kMetres    ? motion.translation().norm()
                               : unit == DeltaUnit::kDegrees ? rad_to_deg(angle)
                                                             : angle);
    previous = current;
  }
  return index;
}

// Pairs (i, j) with index_j closest to index_i + delta, the last pose included (evo's way).
IdPairs closest_delta_pairs(const std::vector<double>& index, double delta) {
  IdPairs pairs;
  for (size_t i = 0; i < index.size(); ++i)
    pairs.push_back({i, find_closest_index(index, index[i] + delta)});
  return pairs;
}

// The length of a step as numpy's norm computes it (squares summed in order).
double step_length(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d step = a - b;
  return std::sqrt(step.x() * step.x() + step.y() * step.y() + step.z() * step.z());
}

// geometry.accumulated_distances: 0, then the running sum of the steps' lengths.
std::vector<double> accumulated_distances(const std::vector<Eigen::Vector3d>& positions) {
  std::vector<double> d(positions.size(), 0.0);
  for (size_t k = 1; k < positions.size(); ++k)
    d[k] = d[k - 1] + step_length(positions[k - 1], positions[k]);
  return d;
}

// filter_pairs_by_path with all_pairs: for each i, the j > i whose path distance from i is
// closest to delta (the first such j on a tie, as numpy's argmin), kept if it is off by at
// most tol. The distances from i do not decrease with j, so a binary search finds j.
IdPairs path_all_pairs(const std::vector<double>& d, double delta, double tol) {
  IdPairs pairs;
  for (size_t i = 0; i + 1 < d.size(); ++i) {
    const auto from_i = [&](size_t j) { return d[j] - d[i]; };
    const auto off = [&](size_t j) { return std::abs(from_i(j) - delta); };
    size_t lo = i + 1, hi = d.size();  // first j with from_i(j) - delta >= 0
    while (lo < hi) {
      const size_t mid = (lo + hi) / 2;
      if (from_i(mid) - delta < 0) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    size_t j = std::min(lo, d.size() - 1);
    if (lo > i + 1 && (lo == d.size() || off(lo - 1) <= off(lo))) {
      // The best is below delta; take the first j of its run of equal distances.
      const double value = from_i(lo - 1);
      size_t first = i + 1, last = lo - 1;
      while (first < last) {
        const size_t mid = (first + last) / 2;
        if (from_i(mid) < value) {
          first = mid + 1;
        } else {
          last = mid;
        }
      }
      j = first;
    }
    if (off(j) > tol) continue;
    pairs.push_back({i, j});
  }
  return pairs;
}

// evo's filters.id_pairs_from_delta on the associated poses P (the estimate's) with their
// unit quaternions Q.
IdPairs evo_pairs(const std::vector<double>& stamps, const PoseAt& P,
                  const std::function<Eigen::Quaterniond(size_t)>& Q, const RpeOptions& o) {
  IdPairs pairs;
  const size_t n = stamps.size();
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
  if (o.unit == DeltaUnit::kMetres) {  // filter_pairs_by_path
    std::vector<Eigen::Vector3d> positions(n);
    for (size_t k = 0; k < n; ++k) positions[k] = P(k).translation();
    if (o.all_pairs)
      return path_all_pairs(accumulated_distances(positions), o.delta, o.delta * o.rel_delta_tol);
    // Consecutive windows: a pose ends one when the path since the last end reaches delta.
    std::vector<size_t> ids;
    double path = 0;
    for (size_t k = 1; k < n; ++k) {
      path += step_length(positions[k], positions[k - 1]);
      if (path >= o.delta) {
        ids.push_back(k);
        path = 0;
      }
    }
    for (size_t k = 1; k < ids.size(); ++k) pairs.push_back({ids[k - 1], ids[k]});
    return pairs;
  }
  if (o.unit == DeltaUnit::kDegrees || o.unit == DeltaUnit::kRadians) {
    // filter_pairs_by_angle (evo pull request 426, Aug 2021)
    const bool degrees = o.unit == DeltaUnit::kDegrees;
    if (o.delta > (degrees ? 180.0 : M_PI))
      throw std::invalid_argument(degrees ? "--delta in degrees must be within [0, 180] (evo's rule)"
                                          : "--delta in radians must be within [0, pi] (evo's rule)");
    const double to_rad = degrees ? M_PI / 180.0 : 1.0;
    const double delta = o.delta * to_rad, tol = o.delta * o.rel_delta_tol * to_rad;
    if (o.all_pairs) {
      // Every j > i whose direct relative angle is within tol of delta; evo compares the poses'
      // unit quaternions here (scipy Rotations), not their matrices.
      std::vector<Eigen::Quaterniond> orientation(n);
      for (size_t k = 0; k < n; ++k) orientation[k] = Q(k);
      for (size_t i = 0; i + 1 < n; ++i) {
        const Eigen::Quaterniond inverse_i = orientation[i].conjugate();
        for (size_t j = i + 1; j < n; ++j) {
          const double angle = Eigen::AngleAxisd(inverse_i * orientation[j]).angle();
          if (delta - tol <= angle && angle <= delta + tol) pairs.push_back({i, j});
        }
      }
      return pairs;
    }
    // Consecutive windows from pose 0: the angles between neighbouring poses accumulate, as
    // path lengths do for metres; a window closes when the sum reaches delta.
    double accumulated = 0;
    size_t start = 0;
    Eigen::Isometry3d previous = n ? P(0) : Eigen::Isometry3d::Identity();
    for (size_t k = 1; k < n; ++k) {
      const Eigen::Isometry3d current = P(k);
      accumulated += rotation_angle(previous.inverse() * current);
      previous = current;
      if (accumulated >= delta) {
        pairs.push_back({start, k});
        accumulated = 0;
        start = k;
      }
    }
    return pairs;
  }
  // Seconds: evo has no time delta; the benchmark's closest-index rule, keeping the last pose
  // like evo's filters do. See eval/README.md.
  return closest_delta_pairs(stamps, o.delta);
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
  trans.reserve(pairs.size());
  rot.reserve(pairs.size());
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
  const std::vector<double>& stamps_est = est.stamps();
  const std::vector<double>& stamps_gt = gt.stamps();
  const PoseAt P = [&](size_t k) { return scaled(est.pose(k), o.scale); };

  std::vector<double> intervals;
  intervals.reserve(stamps_gt.size());
  for (size_t k = 1; k < stamps_gt.size(); ++k)
    intervals.push_back(stamps_gt[k] - stamps_gt[k - 1]);
  const double max_time_diff = 2.0 * compute_stats(intervals).median;

  // Nearest groundtruth pose of each estimated pose, or -1 if too far (computed once).
  std::vector<int64_t> gt_of(est.size(), -1);
  for (size_t k = 0; k < est.size(); ++k) {
    const double t = stamps_est[k] + o.offset;
    const size_t g = find_closest_index(stamps_gt, t);
    if (!(std::abs(stamps_gt[g] - t) > max_time_diff)) gt_of[k] = int64_t(g);
  }

  std::vector<RpePair> out;
  size_t candidates = 0;
  const auto add = [&](size_t i, size_t j) {
    ++candidates;
    if (gt_of[i] < 0 || gt_of[j] < 0) return;
    const size_t g_i = size_t(gt_of[i]), g_j = size_t(gt_of[j]);
    // error44 = ominus(ominus(P_j, P_i), ominus(Q_j, Q_i)) with ominus(a, b) = a^-1 b.
    const Eigen::Isometry3d E =
        (P(j).inverse() * P(i)).inverse() * (gt.pose(g_j).inverse() * gt.pose(g_i));
    out.push_back({stamps_est[i], stamps_est[j], stamps_gt[g_i], stamps_gt[g_j],
                   E.translation().norm(), rad_to_deg(trace_angle(E.rotation()))});
  };
  if (o.all_pairs) {
    for (size_t i = 0; i < est.size(); ++i)
      for (size_t j = i + 1; j < est.size(); ++j) add(i, j);
  } else {
    // Pairs made as they are found (a million-pose list of them would cost 16 MB).
    const std::vector<double> index =
        o.unit == DeltaUnit::kSeconds ? std::vector<double>() : delta_index(stamps_est, P, o.unit);
    const std::vector<double>& delta_of = o.unit == DeltaUnit::kSeconds ? stamps_est : index;
    out.reserve(est.size());
    for (size_t i = 0; i < delta_of.size(); ++i) {
      const size_t j = find_closest_index(delta_of, delta_of[i] + o.delta);
      if (j != delta_of.size() - 1) add(i, j);  // the script's `if j != len(traj_est)-1`
    }
  }
  return finish(std::move(out), est_name, candidates);
}

RpeResult rpe_evo(const Trajectory& gt, const Trajectory& est,
                  const std::vector<IndexPair>& associated, const RpeOptions& o,
                  const std::string& est_name) {
  std::vector<double> stamps(associated.size());
  for (size_t k = 0; k < associated.size(); ++k) stamps[k] = est.stamp(associated[k].second);
  const PoseAt P = [&](size_t k) { return scaled(est.pose(associated[k].second), o.scale); };
  const PoseAt Q = [&](size_t k) { return gt.pose(associated[k].first); };
  const IdPairs pairs = evo_pairs(
      stamps, P, [&](size_t k) { return est.orientation(associated[k].second); }, o);
  std::vector<RpePair> out;
  out.reserve(pairs.size());
  for (const auto& [i, j] : pairs) {
    // evo's rpe_base: E = relative(Q_rel, P_rel), relative(a, b) = a^-1 b.
    const Eigen::Isometry3d E = (Q(i).inverse() * Q(j)).inverse() * (P(i).inverse() * P(j));
    out.push_back({stamps[i], stamps[j], gt.stamp(associated[i].first),
                   gt.stamp(associated[j].first), E.translation().norm(),
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
constexpr EnumNames<DeltaUnit, 5> kDeltaUnitNames = {{{DeltaUnit::kSeconds, "s"},
                                                      {DeltaUnit::kFrames, "f"},
                                                      {DeltaUnit::kMetres, "m"},
                                                      {DeltaUnit::kDegrees, "deg"},
                                                      {DeltaUnit::kRadians, "rad"}}};
constexpr EnumNames<RpeConvention, 2> kConventionNames = {
    {{RpeConvention::kTum, "tum"}, {RpeConvention::kEvo, "evo"}}};
}  // namespace

std::string to_string(DeltaUnit unit) { return name_of(kDeltaUnitNames, unit); }

DeltaUnit parse_delta_unit(const std::string& text) {
  if (const auto unit = value_named(kDeltaUnitNames, text)) return *unit;
  throw std::invalid_argument("unknown delta unit '" + text + "' (use " + choices(kDeltaUnitNames) +
                              ")");
}

std::string to_string(RpeConvention convention) { return name_of(kConventionNames, convention); }

RpeConvention parse_rpe_convention(const std::string& text) {
  if (const auto convention = value_named(kConventionNames, text)) return *convention;
  throw std::invalid_argument("unknown RPE convention '" + text + "' (use " +
                              choices(kConventionNames) + ")");
}

}  // namespace slamkit::eval
