#include "loop/k_medians.h"

#include <random>

#include "features/descriptor.h"

namespace slamkit {
namespace {

// Seeds by k-means++. All integer: the draw is a 64-bit integer below the sum of squared
// distances, so the choice never depends on floating-point rounding or the standard library's
// distribution implementations.
std::vector<Descriptor> kmeanspp_seeds(const std::vector<const uint8_t*>& members, int k,
                                       uint64_t seed) {
  const int n = int(members.size());
  std::mt19937_64 rng(seed);
  std::vector<Descriptor> seeds;
  auto add_seed = [&](int i) {
    Descriptor d;
    std::copy(members[i], members[i] + kDescriptorBytes, d.begin());
    seeds.push_back(d);
  };
  add_seed(int(rng() % uint64_t(n)));
  std::vector<uint64_t> nearest(n, UINT64_MAX);
  while (int(seeds.size()) < k) {
    const uint8_t* last = seeds.back().data();
    uint64_t total = 0;
#pragma omp parallel for reduction(+ : total) if (n > 20000)
    for (int i = 0; i < n; ++i) {
      const uint64_t d = uint64_t(descriptor_distance(members[i], last));
      if (d * d < nearest[i]) nearest[i] = d * d;
      total += nearest[i];
    }
    if (total == 0) break;  // every member equals a seed: no more distinct centres
    uint64_t draw = rng() % total;
    int chosen = 0;
    while (draw >= nearest[chosen]) draw -= nearest[chosen++];
    add_seed(chosen);
  }
  return seeds;
}

// Assigns each member to its nearest centre (the first on ties); returns whether any changed.
bool assign(const std::vector<const uint8_t*>& members, const std::vector<Descriptor>& centres,
            std::vector<int>& assignment) {
  const int n = int(members.size());
  int changed = 0;
#pragma omp parallel for reduction(+ : changed) if (n > 20000)
  for (int i = 0; i < n; ++i) {
    int best = 0, best_distance = kDescriptorBytes * 8 + 1;
    for (int c = 0; c < int(centres.size()); ++c) {
      const int d = descriptor_distance(members[i], centres[c].data());
      if (d < best_distance) {
        best_distance = d;
        best = c;
      }
    }
    if (assignment[i] != best) {
      assignment[i] = best;
      ++changed;
    }
  }
  return changed > 0;
}

std::vector<std::vector<const uint8_t*>> cluster_members(
    const std::vector<const uint8_t*>& members, const std::vector<int>& assignment, size_t k) {
  std::vector<std::vector<const uint8_t*>> clusters(k);
  for (size_t i = 0; i < members.size(); ++i) clusters[assignment[i]].push_back(members[i]);
  return clusters;
}

}  // namespace

Clustering k_medians(const std::vector<const uint8_t*>& members, int k, int max_iterations,
                     uint64_t seed) {
  Clustering result;
  if (members.empty()) return result;
  result.centres = kmeanspp_seeds(members, k, seed);
  result.assignment.assign(members.size(), -1);
  assign(members, result.centres, result.assignment);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const auto clusters = cluster_members(members, result.assignment, result.centres.size());
    for (size_t c = 0; c < clusters.size(); ++c)  // an empty cluster keeps its centre
      if (!clusters[c].empty()) result.centres[c] = majority_descriptor(clusters[c]);
    if (!assign(members, result.centres, result.assignment)) break;
  }
  // Drop clusters left empty, renumbering the others in order.
  std::vector<int> renumber(result.centres.size(), -1);
  std::vector<Descriptor> kept;
  for (int a : result.assignment) renumber[a] = 0;
  for (size_t c = 0; c < renumber.size(); ++c)
    if (renumber[c] == 0) {
      renumber[c] = int(kept.size());
      kept.push_back(result.centres[c]);
    }
  for (int& a : result.assignment) a = renumber[a];
  result.centres = std::move(kept);
  return result;
}

}  // namespace slamkit
