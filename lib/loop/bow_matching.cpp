#include "loop/bow_matching.h"

#include <algorithm>

#include "features/descriptor.h"

namespace slamkit {

std::vector<FeaturePair> match_by_nodes(const FeatureVector& nodes_a, const cv::Mat& descriptors_a,
                                        const FeatureVector& nodes_b, const cv::Mat& descriptors_b,
                                        const BowMatchOptions& options) {
  std::vector<FeaturePair> pairs;
  std::vector<bool> b_matched(descriptors_b.rows, false);
  auto a_node = nodes_a.begin();
  auto b_node = nodes_b.begin();
  while (a_node != nodes_a.end() && b_node != nodes_b.end()) {
    if (a_node->node < b_node->node) {
      ++a_node;
      continue;
    }
    if (b_node->node < a_node->node) {
      ++b_node;
      continue;
    }
    for (int fa : a_node->features) {
      const uint8_t* da = descriptors_a.ptr<uint8_t>(fa);
      int best = -1, best_distance = kDescriptorBytes * 8 + 1, second = kDescriptorBytes * 8 + 1;
      for (int fb : b_node->features) {
        if (b_matched[fb]) continue;
        const int d = descriptor_distance(da, descriptors_b.ptr<uint8_t>(fb));
        if (d < best_distance) {
          second = best_distance;
          best_distance = d;
          best = fb;
        } else if (d < second) {
          second = d;
        }
      }
      if (best >= 0 && best_distance < options.max_distance &&
          best_distance < options.ratio * second) {
        b_matched[best] = true;
        pairs.push_back({fa, best, best_distance});
      }
    }
    ++a_node;
    ++b_node;
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const FeaturePair& x, const FeaturePair& y) { return x.a < y.a; });
  return pairs;
}

}  // namespace slamkit
