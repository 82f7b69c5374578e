#include "loop/bow_vector.h"

#include <algorithm>
#include <cmath>

namespace slamkit {

BowVector normalised_bow(std::vector<BowEntry> entries) {
  std::sort(entries.begin(), entries.end(),
            [](const BowEntry& a, const BowEntry& b) { return a.word < b.word; });
  BowVector bow;
  for (const BowEntry& e : entries) {
    if (!bow.empty() && bow.back().word == e.word)
      bow.back().weight += e.weight;
    else
      bow.push_back(e);
  }
  bow.erase(std::remove_if(bow.begin(), bow.end(), [](const BowEntry& e) { return e.weight <= 0; }),
            bow.end());
  double norm = 0;
  for (const BowEntry& e : bow) norm += e.weight;
  for (BowEntry& e : bow) e.weight /= norm;
  return bow;
}

static double l1_norm(const BowVector& v) {
  double norm = 0;
  for (const BowEntry& e : v) norm += std::abs(e.weight);
  return norm;
}

double l1_score(const BowVector& a, const BowVector& b) {
  const double norm_a = l1_norm(a), norm_b = l1_norm(b);
  if (norm_a == 0 || norm_b == 0) return 0;
  // Walk both sorted vectors at once; a word missing from one side counts its whole weight.
  double distance = 0;
  size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].word < b[j].word)) {
      distance += std::abs(a[i++].weight) / norm_a;
    } else if (i == a.size() || b[j].word < a[i].word) {
      distance += std::abs(b[j++].weight) / norm_b;
    } else {
      distance += std::abs(a[i++].weight / norm_a - b[j++].weight / norm_b);
    }
  }
  return 1 - 0.5 * distance;
}

FeatureVector keep_features(const FeatureVector& nodes, const std::vector<bool>& keep) {
  FeatureVector kept;
  for (const NodeFeatures& n : nodes) {
    NodeFeatures k{n.node, {}};
    for (int f : n.features)
      if (keep.at(f)) k.features.push_back(f);
    if (!k.features.empty()) kept.push_back(std::move(k));
  }
  return kept;
}

}  // namespace slamkit
