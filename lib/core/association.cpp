#include "core/association.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace slamkit {

size_t count_candidate_pairs(const std::vector<double>& first, const std::vector<double>& second,
                             double window, double offset) {
  size_t count = 0;
  for (const double a : first) {
    const double target = a - offset;
    const auto lo = std::lower_bound(second.begin(), second.end(), target - window);
    const auto hi = std::upper_bound(lo, second.end(), target + window);
    count += size_t(hi - lo);
  }
  return count;
}

bool too_crowded_to_associate(const std::vector<double>& first, const std::vector<double>& second,
                              double window, double offset) {
  return count_candidate_pairs(first, second, window, offset) >
         kMaxCandidatesPerStamp * (first.size() + second.size());
}

std::vector<IndexPair> associate_greedy(const std::vector<double>& first,
                                        const std::vector<double>& second, double max_diff,
                                        double offset) {
  // Candidates: for each a, the b's inside the window, found by binary search rather than
  // associate.py's all-pairs loop; the comparisons themselves are the script's.
  struct Candidate {
    double diff;
    size_t a, b;
  };
  std::vector<Candidate> candidates;
  for (size_t i = 0; i < first.size(); ++i) {
    const double target = first[i] - offset;  // b + offset near a
    auto lo = std::lower_bound(second.begin(), second.end(), target - max_diff);
    for (auto it = lo; it != second.end() && *it <= target + max_diff; ++it) {
      const double diff = std::abs(first[i] - (*it + offset));
      if (diff < max_diff) candidates.push_back({diff, i, size_t(it - second.begin())});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [&](const Candidate& x, const Candidate& y) {
    return std::tie(x.diff, first[x.a], second[x.b]) < std::tie(y.diff, first[y.a], second[y.b]);
  });
  std::vector<bool> used_a(first.size(), false), used_b(second.size(), false);
  std::vector<IndexPair> matches;
  for (const Candidate& c : candidates) {
    if (used_a[c.a] || used_b[c.b]) continue;
    used_a[c.a] = used_b[c.b] = true;
    matches.push_back({c.a, c.b});
  }
  std::sort(matches.begin(), matches.end(),
            [](const IndexPair& x, const IndexPair& y) { return x.first < y.first; });
  return matches;
}

}  // namespace slamkit
