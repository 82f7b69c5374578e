#pragma once
// Training a vocabulary (docs/method.md#loop-closing): hierarchical k-medians on the training
// images' descriptors, then each word's IDF.
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/vocabulary_settings.h"
#include "loop/vocabulary.h"

namespace slamkit {

// `images` holds one descriptor matrix per training image (CV_8U, n x 32, as FrameFeatures
// has them). The tree is built level by level: every node with more than one descriptor is
// split by k_medians() into at most `branching` children, down to `depth` levels; nodes are
// numbered breadth first. Each node's k-means++ draws are seeded by (settings.seed, node id),
// so the tree depends on nothing but the input and the settings (not on thread count).
// Word weights are IDF = log(N / n_i), N the images and n_i those with a feature in word i
// (a word no training image reaches gets log N, as if seen once).
Vocabulary train_vocabulary(const std::vector<cv::Mat>& images,
                            const VocabularySettings& settings);

}  // namespace slamkit
