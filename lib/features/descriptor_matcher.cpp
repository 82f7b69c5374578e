#include "features/descriptor_matcher.h"

#include <algorithm>
#include <opencv2/features2d.hpp>
#include <opencv2/flann.hpp>

namespace slamkit {
namespace {

// The k nearest train rows of every query row (fewer where LSH finds fewer candidates).
std::vector<std::vector<cv::DMatch>> nearest(const cv::Mat& query, const cv::Mat& train, int k,
                                             const MatcherSettings& settings) {
  std::vector<std::vector<cv::DMatch>> knn;
  k = std::min(k, train.rows);  // FLANN asserts k <= rows (a train set of one descriptor)
  if (settings.backend == MatcherBackend::kBruteForce) {
    cv::BFMatcher(cv::NORM_HAMMING).knnMatch(query, train, knn, k);
    return knn;
  }
  cv::FlannBasedMatcher flann(cv::makePtr<cv::flann::LshIndexParams>(
      settings.lsh_table_number, settings.lsh_key_size, settings.lsh_multi_probe_level));
  flann.add(std::vector<cv::Mat>{train});
  // FLANN's LSH tables pick their hash bits with cv::randShuffle, i.e. this thread's
  // cv::theRNG(), whose state carries over between calls. Seed it for the build only and
  // give the caller's state back.
  const cv::RNG caller_rng = cv::theRNG();
  cv::theRNG() = cv::RNG(settings.lsh_seed);
  flann.train();
  cv::theRNG() = caller_rng;
  flann.knnMatch(query, knn, k);
  return knn;
}

}  // namespace

std::vector<cv::DMatch> match_descriptors(const cv::Mat& query, const cv::Mat& train,
                                          const MatcherSettings& settings) {
  std::vector<cv::DMatch> matches;
  if (query.empty() || train.empty()) return matches;
  const std::vector<std::vector<cv::DMatch>> forward = nearest(query, train, 2, settings);
  std::vector<std::vector<cv::DMatch>> backward;
  if (settings.mutual_check) backward = nearest(train, query, 1, settings);

  for (const std::vector<cv::DMatch>& candidates : forward) {
    if (candidates.empty() || candidates[0].trainIdx < 0) continue;
    const cv::DMatch& best = candidates[0];
    if (best.distance > settings.max_distance) continue;
    if (candidates.size() > 1 && candidates[1].trainIdx >= 0 &&
        best.distance >= settings.ratio * candidates[1].distance) {
      continue;
    }
    if (settings.mutual_check) {
      const std::vector<cv::DMatch>& back = backward[best.trainIdx];
      if (back.empty() || back[0].trainIdx != best.queryIdx) continue;
    }
    matches.push_back(best);
  }
  return matches;
}

}  // namespace slamkit
