#pragma once
// A bag-of-words vocabulary of binary ORB descriptors (the textbook's,
// docs/method.md#loop-closing): a k-ary tree of depth L whose leaves are the words, each word
// weighted by its IDF.
//
// Written here from the definitions: no well-kept bag-of-words library is packaged for
// Debian 12 (DBoW2, DBoW3 and fbow are not).
//
// How the loop closer uses it:
//   Vocabulary voc = load_vocabulary(path);          // or train_vocabulary(), vocabulary_file.h
//   ImageBow kf = voc.transform(descriptors, level);  // per keyframe, once
//   database.add(id, kf.words);                       // keyframe_database.h: queries
//   match_by_nodes(kf.nodes, ..., other.nodes, ...);  // bow_matching.h: guided matching
#include <opencv2/core.hpp>
#include <vector>

#include "loop/binary_descriptor.h"
#include "loop/bow_vector.h"

namespace slamkit {

// One node as files store it. Parents come before their children; node 0 is the root, whose
// descriptor is unused. `weight` matters for leaves only (the word's IDF).
struct VocabularyNode {
  NodeId parent = 0;
  Descriptor descriptor{};
  double weight = 0;
};

// An image in words: its bag-of-words vector and its direct index at the chosen level.
struct ImageBow {
  BowVector words;
  FeatureVector nodes;
};

class Vocabulary {
 public:
  Vocabulary() = default;
  // Links the nodes into a tree: the children of a node are the nodes naming it as parent, in
  // node order; nodes without children are the words, numbered in node order. `nodes` must
  // start with the root and list every parent before its children (throws std::invalid_argument
  // otherwise).
  Vocabulary(int branching, int depth, std::vector<VocabularyNode> nodes);

  int branching() const { return branching_; }
  int depth() const { return depth_; }  // L as built or declared; the deepest leaf is at most L
  size_t word_count() const { return node_of_word_.size(); }
  bool empty() const { return node_of_word_.empty(); }
  const std::vector<VocabularyNode>& nodes() const { return nodes_; }
  double weight(WordId word) const { return nodes_[node_of_word_[word]].weight; }
  int level(NodeId node) const { return level_[node]; }  // the root is level 0
  // Replaces every word's weight (training sets the IDF after building the tree).
  void set_weights(const std::vector<double>& word_weights);

  // The word of a descriptor: from the root, down to the child whose centre is nearest in
  // Hamming distance (the first such child on ties), until a leaf.
  WordId transform(const uint8_t* descriptor) const;
  // Also the node passed at `level` (0 = root; the leaf when the leaf is shallower).
  WordId transform(const uint8_t* descriptor, int level, NodeId* node_at_level) const;
  // Every row of `descriptors` (CV_8U, n x 32): the TF x IDF vector (each feature adds its
  // word's weight, then L1 normalisation) and the direct index at `direct_index_level`.
  ImageBow transform(const cv::Mat& descriptors, int direct_index_level) const;

 private:
  int branching_ = 0;
  int depth_ = 0;
  std::vector<VocabularyNode> nodes_;
  std::vector<uint32_t> child_begin_;  // children of node n: children_[child_begin_[n] ..
  std::vector<NodeId> children_;       // child_begin_[n + 1])
  std::vector<int> level_;
  std::vector<int64_t> word_of_node_;  // -1 for inner nodes
  std::vector<NodeId> node_of_word_;
};

}  // namespace slamkit
