#pragma once
// Bag-of-words vocabulary settings (docs/method.md#loop-closing): training of the k-ary tree and
// the level of its direct index.
#include <cstdint>

namespace slamkit {

struct VocabularySettings {
  int branching = 10;    // (slamkit) k, children per node; 10 and 5 give a generic vocabulary
  int depth = 5;         // (slamkit) L, levels below the root; leaves are the words
  int iterations = 10;   // (slamkit) k-medians iterations per node at most (stops when stable)
  uint64_t seed = 2024;  // (slamkit) seeds k-means++ at every node: same input, same tree
  int frame_step = 5;    // (slamkit) `vocab train` extracts features from every n-th frame
  // (ORB-SLAM2) Level (0 = root) whose nodes group features for guided matching. ORB-SLAM2
  // uses 4 levels up from the leaves of its 6-level tree, i.e. level 2; a deeper level matches
  // faster and misses more. Clamped to the tree's depth.
  int direct_index_level = 2;
};

}  // namespace slamkit
