#include "datasets/synth/revisits.h"

#include <cmath>

#include "core/pose.h"

namespace slamkit::synth {

std::vector<RevisitRange> true_revisits(const std::vector<Eigen::Isometry3d>& T_w_c,
                                        const RevisitCriteria& criteria) {
  const int n = int(T_w_c.size());
  const double max_angle = criteria.max_angle_deg * M_PI / 180.0;
  // revisited[j] lists, in increasing order, the earlier frames j revisits.
  std::vector<std::vector<int>> revisited(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& p = T_w_c[i].translation();
    bool left = false;
    for (int j = i + 1; j < n; ++j) {
      const double distance = (T_w_c[j].translation() - p).norm();
      left = left || distance > criteria.min_excursion_m;
      if (left && distance <= criteria.max_distance_m &&
          rotation_angle(T_w_c[i].inverse() * T_w_c[j]) <= max_angle)
        revisited[j].push_back(i);
    }
  }
  std::vector<RevisitRange> ranges;
  for (int j = 0; j < n; ++j)
    for (const int i : revisited[j]) {
      if (!ranges.empty() && ranges.back().later == j && ranges.back().last == i - 1)
        ranges.back().last = i;
      else
        ranges.push_back({j, i, i});
    }
  return ranges;
}

}  // namespace slamkit::synth
