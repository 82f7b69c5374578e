#include "loop/bow_vector.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

TEST(BowVector, IdenticalVectorsScoreOne) {
  const BowVector a = normalised_bow({{3, 0.2}, {7, 1.5}, {9, 0.3}});
  EXPECT_DOUBLE_EQ(l1_score(a, a), 1.0);
  EXPECT_DOUBLE_EQ(l1_score(a, normalised_bow({{3, 0.4}, {7, 3.0}, {9, 0.6}})), 1.0)
      << "scaling does not change an image";
}

TEST(BowVector, DisjointVectorsScoreZero) {
  EXPECT_DOUBLE_EQ(l1_score(normalised_bow({{1, 1}, {2, 1}}), normalised_bow({{3, 1}, {4, 2}})),
                   0.0);
  EXPECT_DOUBLE_EQ(l1_score({}, normalised_bow({{3, 1}})), 0.0);
}

TEST(BowVector, ScoreFollowsTheDefinition) {
  // |a - b|_1 = 0.5 + 0 + 0.5, so s = 1 - 0.5 * 1 = 0.5; unnormalised inputs are normalised.
  const BowVector a = {{1, 1.0}, {2, 1.0}};
  const BowVector b = {{2, 2.0}, {3, 2.0}};
  EXPECT_DOUBLE_EQ(l1_score(a, b), 0.5);
}

TEST(BowVector, NormalisationMergesRepeatedWordsAndDropsZeroWeights) {
  const BowVector v = normalised_bow({{5, 1.0}, {2, 2.0}, {5, 1.0}, {8, 0.0}});
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].word, 2u);
  EXPECT_DOUBLE_EQ(v[0].weight, 0.5);
  EXPECT_EQ(v[1].word, 5u);
  EXPECT_DOUBLE_EQ(v[1].weight, 0.5);
}

TEST(BowVector, KeepFeaturesFiltersTheDirectIndex) {
  const FeatureVector nodes = {{4, {0, 2}}, {9, {1}}};
  const FeatureVector kept = keep_features(nodes, {true, false, false});
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].node, 4u);
  EXPECT_EQ(kept[0].features, std::vector<int>{0});
}

}  // namespace
}  // namespace slamkit
