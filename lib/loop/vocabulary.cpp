#include "loop/vocabulary.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "features/descriptor.h"

namespace slamkit {

Vocabulary::Vocabulary(int branching, int depth, std::vector<VocabularyNode> nodes)
    : branching_(branching), depth_(depth), nodes_(std::move(nodes)) {
  const size_t n = nodes_.size();
  if (n == 0) throw std::invalid_argument("a vocabulary needs at least its root node");
  level_.assign(n, 0);
  std::vector<uint32_t> child_count(n, 0);
  for (size_t i = 1; i < n; ++i) {
    const NodeId parent = nodes_[i].parent;
    if (parent >= i)
      throw std::invalid_argument("node " + std::to_string(i) + " comes before its parent " +
                                  std::to_string(parent));
    level_[i] = level_[parent] + 1;
    ++child_count[parent];
  }
  // Children grouped by parent (counting sort keeps node order within a parent).
  child_begin_.assign(n + 1, 0);
  for (size_t i = 0; i < n; ++i) child_begin_[i + 1] = child_begin_[i] + child_count[i];
  children_.resize(n - 1);
  std::vector<uint32_t> next(child_begin_.begin(), child_begin_.end() - 1);
  for (size_t i = 1; i < n; ++i) children_[next[nodes_[i].parent]++] = NodeId(i);

  word_of_node_.assign(n, -1);
  for (size_t i = 0; i < n; ++i)
    if (child_count[i] == 0 && i > 0) {
      word_of_node_[i] = int64_t(node_of_word_.size());
      node_of_word_.push_back(NodeId(i));
    }
}

void Vocabulary::set_weights(const std::vector<double>& word_weights) {
  if (word_weights.size() != node_of_word_.size())
    throw std::invalid_argument("set_weights: one weight per word is needed");
  for (size_t w = 0; w < word_weights.size(); ++w) nodes_[node_of_word_[w]].weight = word_weights[w];
}

WordId Vocabulary::transform(const uint8_t* descriptor) const {
  NodeId unused;
  return transform(descriptor, 0, &unused);
}

WordId Vocabulary::transform(const uint8_t* descriptor, int level, NodeId* node_at_level) const {
  NodeId node = 0;
  *node_at_level = 0;
  while (child_begin_[node] != child_begin_[node + 1]) {
    NodeId best = 0;
    int best_distance = kDescriptorBytes * 8 + 1;
    for (uint32_t c = child_begin_[node]; c < child_begin_[node + 1]; ++c) {
      const int d = descriptor_distance(nodes_[children_[c]].descriptor.data(), descriptor);
      if (d < best_distance) {
        best_distance = d;
        best = children_[c];
      }
    }
    node = best;
    if (level_[node] <= level) *node_at_level = node;
  }
  return WordId(word_of_node_[node]);
}

ImageBow Vocabulary::transform(const cv::Mat& descriptors, int direct_index_level) const {
  ImageBow image;
  if (empty() || descriptors.empty()) return image;
  std::vector<BowEntry> entries;
  entries.reserve(descriptors.rows);
  std::map<NodeId, std::vector<int>> by_node;
  for (int i = 0; i < descriptors.rows; ++i) {
    NodeId node;
    const WordId word = transform(descriptors.ptr<uint8_t>(i), direct_index_level, &node);
    entries.push_back({word, weight(word)});
    by_node[node].push_back(i);
  }
  image.words = normalised_bow(std::move(entries));
  for (auto& [node, features] : by_node) image.nodes.push_back({node, std::move(features)});
  return image;
}

}  // namespace slamkit
