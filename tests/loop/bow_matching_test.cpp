#include "loop/bow_matching.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "loop/loop_test_support.h"
#include "loop/vocabulary_training.h"

namespace slamkit {
namespace {

TEST(BowMatching, FindsTheSameSceneFeaturesInAnotherImage) {
  auto images = test::clustered_images(20, 300, 2000, 8);
  std::mt19937 rng(3);
  const cv::Mat a = test::random_descriptors(300, rng);
  images.push_back(a);
  VocabularySettings settings;
  settings.branching = 8;
  settings.depth = 3;
  const Vocabulary vocabulary = train_vocabulary(images, settings);

  // b holds a's features shuffled, each with a few bits of noise.
  std::vector<int> order(a.rows);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  cv::Mat b(a.rows, a.cols, CV_8U);
  for (int i = 0; i < a.rows; ++i) a.row(order[i]).copyTo(b.row(i));
  b = test::flip_bits(b, 3, rng);

  const ImageBow bow_a = vocabulary.transform(a, 2);
  const ImageBow bow_b = vocabulary.transform(b, 2);
  const auto pairs = match_by_nodes(bow_a.nodes, a, bow_b.nodes, b);
  // Random descriptors lie far from every centre, so 3 bits of noise move some of them to
  // another node at level 2 (79% stay matched here): missed, never mismatched.
  EXPECT_GT(pairs.size(), 0.7 * a.rows);
  for (const FeaturePair& p : pairs) {
    EXPECT_EQ(order[p.b], p.a);
    EXPECT_LE(p.distance, 3);
  }
  EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end(),
                             [](const FeaturePair& x, const FeaturePair& y) { return x.a < y.a; }));

  // Only the kept features take part.
  std::vector<bool> keep(a.rows, false);
  keep[pairs[0].a] = true;
  const auto kept = match_by_nodes(keep_features(bow_a.nodes, keep), a, bow_b.nodes, b);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].a, pairs[0].a);
}

TEST(BowMatching, AmbiguousAndDistantFeaturesStayUnmatched) {
  std::mt19937 rng(4);
  const cv::Mat a = test::random_descriptors(2, rng);
  cv::Mat b;
  b.push_back(a.row(0));                   // feature 0 has two equal candidates: ratio fails
  b.push_back(a.row(0));
  cv::Mat far = a.row(1).clone();  // feature 1 differs in 64 bits: too far (TH_LOW 50)
  for (int i = 0; i < 8; ++i) far.at<uint8_t>(0, i) ^= 0xff;
  b.push_back(far);
  const FeatureVector all_a = {{1, {0, 1}}};
  const FeatureVector all_b = {{1, {0, 1, 2}}};
  EXPECT_TRUE(match_by_nodes(all_a, a, all_b, b).empty());
  BowMatchOptions loose;
  loose.ratio = 1.01;
  loose.max_distance = 257;
  const auto pairs = match_by_nodes(all_a, a, all_b, b, loose);
  ASSERT_EQ(pairs.size(), 1u) << "a tie never passes a ratio test";
  EXPECT_EQ(pairs[0].a, 1);
  EXPECT_EQ(pairs[0].b, 2);
  EXPECT_EQ(pairs[0].distance, 64);
}

}  // namespace
}  // namespace slamkit
