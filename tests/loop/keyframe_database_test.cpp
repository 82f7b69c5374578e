#include "loop/keyframe_database.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

KeyframeDatabase three_keyframes() {
  KeyframeDatabase db;
  db.add(10, normalised_bow({{1, 1}, {2, 1}, {3, 1}}));
  db.add(11, normalised_bow({{1, 1}, {2, 1}, {4, 1}}));
  db.add(12, normalised_bow({{4, 1}, {5, 1}}));
  db.add(13, normalised_bow({{8, 1}}));
  return db;
}

TEST(KeyframeDatabase, QueryScoresAreTheL1ScoreBestFirst) {
  const KeyframeDatabase db = three_keyframes();
  const BowVector query = normalised_bow({{1, 1}, {2, 1}, {3, 2}});
  const auto candidates = db.query(query);
  ASSERT_EQ(candidates.size(), 2u) << "only keyframes sharing a word";
  EXPECT_EQ(candidates[0].keyframe, 10);
  EXPECT_EQ(candidates[0].shared_words, 3);
  EXPECT_NEAR(candidates[0].score, l1_score(query, normalised_bow({{1, 1}, {2, 1}, {3, 1}})),
              1e-12);
  EXPECT_EQ(candidates[1].keyframe, 11);
  EXPECT_EQ(candidates[1].shared_words, 2);
  EXPECT_NEAR(candidates[1].score, l1_score(query, normalised_bow({{1, 1}, {2, 1}, {4, 1}})),
              1e-12);
}

TEST(KeyframeDatabase, ExcludedKeyframesAreNeverReturned) {
  const KeyframeDatabase db = three_keyframes();
  BowQuery options;
  options.exclude = {10};
  const auto candidates = db.query(normalised_bow({{1, 1}, {2, 1}, {3, 2}}), options);
  ASSERT_EQ(candidates.size(), 1u);
  EXPECT_EQ(candidates[0].keyframe, 11);
}

TEST(KeyframeDatabase, MinScoreAndMaxResultsTrimTheList) {
  const KeyframeDatabase db = three_keyframes();
  const BowVector query = normalised_bow({{1, 1}, {4, 1}});
  EXPECT_EQ(db.query(query).size(), 3u);
  BowQuery best;
  best.max_results = 1;
  ASSERT_EQ(db.query(query, best).size(), 1u);
  EXPECT_EQ(db.query(query, best)[0].keyframe, 11);
  BowQuery strong;
  strong.min_score = 0.6;
  EXPECT_EQ(db.query(query, strong).size(), 1u);
}

TEST(KeyframeDatabase, EraseAndReAddReplaceTheKeyframe) {
  KeyframeDatabase db = three_keyframes();
  db.erase(10);
  db.erase(99);  // unknown: ignored
  EXPECT_FALSE(db.contains(10));
  EXPECT_EQ(db.size(), 3u);
  EXPECT_TRUE(db.query(normalised_bow({{3, 1}})).empty());
  db.add(11, normalised_bow({{3, 1}}));
  const auto candidates = db.query(normalised_bow({{3, 1}}));
  ASSERT_EQ(candidates.size(), 1u);
  EXPECT_DOUBLE_EQ(candidates[0].score, 1.0);
  EXPECT_TRUE(db.query(normalised_bow({{2, 1}})).empty()) << "the old words of 11 are gone";
}

}  // namespace
}  // namespace slamkit
