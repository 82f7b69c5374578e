#pragma once
// Images as bag-of-words vectors (docs/method.md#loop-closing), and the direct index of one
// image.
#include <cstdint>
#include <vector>

namespace slamkit {

using WordId = uint32_t;  // a leaf of the vocabulary tree, numbered 0..words-1
using NodeId = uint32_t;  // any node of the tree; 0 is the root

struct BowEntry {
  WordId word;
  double weight;
};

// Sparse vector of positive weights, sorted by word, one entry a word, L1 norm 1 (or empty).
using BowVector = std::vector<BowEntry>;

// Sums the weights of repeated words, drops words whose weight is 0 (a word in every training
// image carries no information), sorts by word and scales to L1 norm 1.
BowVector normalised_bow(std::vector<BowEntry> entries);

// The L1 score s(a, b) = 1 - 0.5 |a/|a| - b/|b||_1 (docs/method.md#loop-closing): 1 for the
// same vector, 0 when no word is shared. 0 when either vector is empty.
double l1_score(const BowVector& a, const BowVector& b);

// The direct index of one image: the features (row indices into its descriptor matrix) under
// each node of a chosen tree level, sorted by node; features under different nodes are
// unlikely to match, so guided matching compares only those under the same node.
struct NodeFeatures {
  NodeId node;
  std::vector<int> features;  // ascending
};
using FeatureVector = std::vector<NodeFeatures>;

// The features for which keep[feature] is true (e.g. those with a map point), nodes left empty
// dropped. `keep` must cover every feature index.
FeatureVector keep_features(const FeatureVector& nodes, const std::vector<bool>& keep);

}  // namespace slamkit
