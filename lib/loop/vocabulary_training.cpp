#include "loop/vocabulary_training.h"

#include <cmath>
#include <stdexcept>

#include "loop/k_medians.h"

namespace slamkit {
namespace {

// SplitMix64's finaliser: a well-spread seed per node from the run's seed and the node id.
uint64_t node_seed(uint64_t seed, NodeId node) {
  uint64_t z = seed + 0x9e3779b97f4a7c15ull * (uint64_t(node) + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

struct Split {
  NodeId node;
  std::vector<const uint8_t*> members;
};

std::vector<VocabularyNode> build_tree(const std::vector<cv::Mat>& images,
                                       const VocabularySettings& settings) {
  std::vector<VocabularyNode> nodes(1);  // the root
  std::vector<Split> level{{0, {}}};
  for (const cv::Mat& image : images) {
    if (!image.empty() && (image.type() != CV_8U || image.cols != kDescriptorBytes))
      throw std::invalid_argument("train_vocabulary: descriptors must be CV_8U n x 32");
    for (int r = 0; r < image.rows; ++r) level[0].members.push_back(image.ptr<uint8_t>(r));
  }
  for (int depth = 1; depth <= settings.depth && !level.empty(); ++depth) {
    // The level's nodes split independently (each with its own seed): in parallel, then linked
    // in order, so the tree is the same at any thread count. A single node (the root) is
    // parallel inside k_medians instead.
    std::vector<Clustering> clusterings(level.size());
#pragma omp parallel for schedule(dynamic) if (level.size() > 1)
    for (long i = 0; i < long(level.size()); ++i) {
      const Split& split = level[size_t(i)];
      if (split.members.size() < 2) continue;  // a leaf
      clusterings[size_t(i)] = k_medians(split.members, settings.branching, settings.iterations,
                                         node_seed(settings.seed, split.node));
    }
    std::vector<Split> next;
    for (size_t i = 0; i < level.size(); ++i) {
      const Split& split = level[i];
      const Clustering& c = clusterings[i];
      if (c.centres.size() < 2) continue;  // a leaf, or identical members: nothing to split
      const size_t first = next.size();
      for (const Descriptor& centre : c.centres) {
        next.push_back({NodeId(nodes.size()), {}});
        nodes.push_back({split.node, centre, 0});
      }
      for (size_t m = 0; m < split.members.size(); ++m)
        next[first + c.assignment[m]].members.push_back(split.members[m]);
    }
    level = std::move(next);
  }
  return nodes;
}

std::vector<double> inverse_document_frequency(const Vocabulary& vocabulary,
                                               const std::vector<cv::Mat>& images) {
  std::vector<int> images_with_word(vocabulary.word_count(), 0);
  std::vector<int> last_image(vocabulary.word_count(), -1);
  for (size_t i = 0; i < images.size(); ++i)
    for (int r = 0; r < images[i].rows; ++r) {
      const WordId w = vocabulary.transform(images[i].ptr<uint8_t>(r));
      if (last_image[w] != int(i)) {
        last_image[w] = int(i);
        ++images_with_word[w];
      }
    }
  std::vector<double> idf(vocabulary.word_count());
  for (size_t w = 0; w < idf.size(); ++w)
    idf[w] = std::log(double(images.size()) / std::max(images_with_word[w], 1));
  return idf;
}

}  // namespace

Vocabulary train_vocabulary(const std::vector<cv::Mat>& images,
                            const VocabularySettings& settings) {
  Vocabulary vocabulary(settings.branching, settings.depth, build_tree(images, settings));
  if (!vocabulary.empty()) vocabulary.set_weights(inverse_document_frequency(vocabulary, images));
  return vocabulary;
}

}  // namespace slamkit
