#pragma once
// Guided matching of two images through the vocabulary's direct index (ORB-SLAM2's
// SearchByBoW): a feature is compared only with the other image's features under the same
// tree node, which is far fewer comparisons than brute force and keeps look-alike features of
// different words apart.
#include <opencv2/core.hpp>
#include <vector>

#include "loop/bow_vector.h"

namespace slamkit {

struct BowMatchOptions {
  int max_distance = 50;  // Hamming bits, a match must be below it (ORB-SLAM2's TH_LOW)
  double ratio = 0.75;    // best below ratio x second best (ORB-SLAM2's loop and relocalisation)
};

struct FeaturePair {
  int a;         // row of descriptors_a
  int b;         // row of descriptors_b
  int distance;  // Hamming bits
};

// For each feature of `a` (nodes in node order, features in the order listed), its nearest
// feature of `b` under the same node among those not yet matched, kept when it passes both
// tests; every b feature is matched at most once. To match only some features (e.g. those with
// a map point), pass keep_features() of the direct indices. Sorted by a.
std::vector<FeaturePair> match_by_nodes(const FeatureVector& nodes_a, const cv::Mat& descriptors_a,
                                        const FeatureVector& nodes_b, const cv::Mat& descriptors_b,
                                        const BowMatchOptions& options = {});

}  // namespace slamkit
