#include "eval/metrics/association.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "core/enum_names.h"
#include "core/error.h"

namespace slamkit::eval {

namespace {

// evo's matching_time_indices for one stamp: the first index j minimising
// |(longer[j] + shift) - stamp| (numpy's argmin), if that is at most max_diff.
std::optional<size_t> nearest_evo(const std::vector<double>& longer, double shift, double stamp,
                                  double max_diff) {
  if (longer.empty()) return std::nullopt;
  // longer[j] + shift does not decrease with j, so the minimum is next to the first j at or
  // after the stamp.
  const auto first_after = std::partition_point(longer.begin(), longer.end(),
                                                [&](double t) { return t + shift < stamp; });
  size_t best =
      first_after == longer.end() ? longer.size() - 1 : size_t(first_after - longer.begin());
  const auto diff = [&](size_t j) { return std::abs((longer[j] + shift) - stamp); };
  if (best > 0 && diff(best - 1) <= diff(best)) --best;
  while (best > 0 && longer[best - 1] == longer[best]) --best;  // argmin: first of equal stamps
  if (!(diff(best) <= max_diff)) return std::nullopt;
  return best;
}

// associate.py's candidate test, exactly as core/association.cpp applies it.
bool is_candidate(double gt_stamp, double est_stamp, double max_diff, double offset) {
  const double target = gt_stamp - offset;
  return est_stamp >= target - max_diff && est_stamp <= target + max_diff &&
         std::abs(gt_stamp - (est_stamp + offset)) < max_diff;
}

// The benchmark's greedy association (associate_greedy) with the easy part done first: a pair
// that is the best candidate of both its poses (by associate.py's order: difference, then
// stamps) is taken by the greedy rule whatever else happens (no candidate with a smaller
// difference touches either pose), so it is fixed without sorting; the greedy rule then runs
// on the poses left over, with the candidates among them, which completes the same matching.
// On a million poses this avoids sorting millions of candidates.
std::vector<IndexPair> associate_tum(const std::vector<double>& gt, const std::vector<double>& est,
                                     double max_diff, double offset) {
  constexpr size_t kNone = SIZE_MAX;
  // Best candidate of each groundtruth pose: smallest difference, then earliest estimate.
  std::vector<size_t> best_est(gt.size(), kNone), best_gt(est.size(), kNone);
  for (size_t g = 0; g < gt.size(); ++g) {
    double best = max_diff;
    const auto from = std::lower_bound(est.begin(), est.end(), gt[g] - offset - 2 * max_diff);
    for (auto it = from; it != est.end() && *it <= gt[g] - offset + 2 * max_diff; ++it) {
      if (!is_candidate(gt[g], *it, max_diff, offset)) continue;
      const double diff = std::abs(gt[g] - (*it + offset));
      if (best_est[g] == kNone || diff < best) {
        best = diff;
        best_est[g] = size_t(it - est.begin());
      }
    }
  }
  for (size_t e = 0; e < est.size(); ++e) {  // smallest difference, then earliest groundtruth
    double best = max_diff;
    const auto from = std::lower_bound(gt.begin(), gt.end(), est[e] + offset - 2 * max_diff);
    for (auto it = from; it != gt.end() && *it <= est[e] + offset + 2 * max_diff; ++it) {
      if (!is_candidate(*it, est[e], max_diff, offset)) continue;
      const double diff = std::abs(*it - (est[e] + offset));
      if (best_gt[e] == kNone || diff < best) {
        best = diff;
        best_gt[e] = size_t(it - gt.begin());
      }
    }
  }
  std::vector<IndexPair> pairs;
  std::vector<size_t> rest_gt, rest_est;
  std::vector<double> rest_gt_stamps, rest_est_stamps;
  for (size_t g = 0; g < gt.size(); ++g) {
    if (best_est[g] != kNone && best_gt[best_est[g]] == g) {
      pairs.push_back({g, best_est[g]});
    } else {
      rest_gt.push_back(g);
      rest_gt_stamps.push_back(gt[g]);
    }
  }
  for (size_t e = 0; e < est.size(); ++e) {
    if (best_gt[e] != kNone && best_est[best_gt[e]] == e) continue;
    rest_est.push_back(e);
    rest_est_stamps.push_back(est[e]);
  }
  for (const IndexPair& p : associate_greedy(rest_gt_stamps, rest_est_stamps, max_diff, offset))
    pairs.push_back({rest_gt[p.first], rest_est[p.second]});
  return pairs;
}

}  // namespace

std::vector<IndexPair> associate(const Trajectory& gt, const Trajectory& est,
                                 const AssociationOptions& options) {
  std::vector<IndexPair> pairs;
  if (options.method == AssociationMethod::kTum) {
    pairs = associate_tum(gt.stamps(), est.stamps(), options.max_diff, options.offset);
  } else if (est.size() > gt.size()) {  // evo loops over the shorter list
    for (size_t g = 0; g < gt.size(); ++g)
      if (const auto e = nearest_evo(est.stamps(), options.offset, gt.stamp(g), options.max_diff))
        pairs.push_back({g, *e});
  } else {
    for (size_t e = 0; e < est.size(); ++e)
      if (const auto g = nearest_evo(gt.stamps(), -options.offset, est.stamp(e), options.max_diff))
        pairs.push_back({*g, e});
  }
  std::sort(pairs.begin(), pairs.end(), [](const IndexPair& a, const IndexPair& b) {
    return std::tie(a.second, a.first) < std::tie(b.second, b.first);
  });
  return pairs;
}

void require_associable(const Trajectory& gt, const Trajectory& est, const std::string& gt_name,
                        const std::string& est_name, const AssociationOptions& options) {
  // associate_tum looks at the poses within twice the tolerance; evo's rule is a binary search.
  if (options.method != AssociationMethod::kTum ||
      !too_crowded_to_associate(gt.stamps(), est.stamps(), 2 * options.max_diff, options.offset))
    return;
  throw_input_error(est_name, "timestamps too crowded to associate with " + gt_name + ": over " +
                                  std::to_string(kMaxCandidatesPerStamp) +
                                  " poses within the tolerance of each other on average (stamps "
                                  "not in seconds? see --time-unit)");
}

void require_enough_pairs(size_t pair_count, const Trajectory& gt, const Trajectory& est,
                          const std::string& gt_name, const std::string& est_name,
                          const AssociationOptions& options) {
  if (pair_count >= 2) return;
  char text[1024];
  std::snprintf(text, sizeof text,
                "only %zu estimated pose(s) matched groundtruth within %g s (offset %g s, %s "
                "association); groundtruth %s has %zu poses over %.6f .. %.6f, estimate %s "
                "has %zu poses over %.6f .. %.6f; are these the right files (or is a time "
                "offset needed)?",
                pair_count, options.max_diff, options.offset, to_string(options.method).c_str(),
                gt_name.c_str(), gt.size(), gt.start_time(), gt.end_time(), est_name.c_str(),
                est.size(), est.start_time(), est.end_time());
  throw_input_error(est_name, text);
}

namespace {
constexpr EnumNames<AssociationMethod, 2> kAssociationNames = {
    {{AssociationMethod::kTum, "tum"}, {AssociationMethod::kEvo, "evo"}}};
}  // namespace

std::string to_string(AssociationMethod method) { return name_of(kAssociationNames, method); }

AssociationMethod parse_association_method(const std::string& text) {
  if (const auto method = value_named(kAssociationNames, text)) return *method;
  throw std::invalid_argument("unknown association '" + text + "' (use " +
                              choices(kAssociationNames) + ")");
}

}  // namespace slamkit::eval
