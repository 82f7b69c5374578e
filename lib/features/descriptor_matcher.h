#pragma once
// Matching two sets of ORB descriptors by Hamming distance (docs/method.md#matching-and-pose).
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/matcher_settings.h"

namespace slamkit {

// At most one match per query row: its nearest train row by FLANN LSH (paper) or brute force,
// kept when within max_distance, passing the ratio test and, if asked, the mutual check.
// Sorted by queryIdx; DMatch::distance is the Hamming distance. Deterministic: the LSH tables
// are drawn from a generator seeded with settings.lsh_seed.
std::vector<cv::DMatch> match_descriptors(const cv::Mat& query, const cv::Mat& train,
                                          const MatcherSettings& settings);

}  // namespace slamkit
