#include "core/association.h"

#include <gtest/gtest.h>

namespace slamkit {
namespace {

TEST(AssociateGreedy, TakesSmallestDifferencesFirstAndUsesEachStampOnce) {
  // b=1.012 is nearest to both a=1.0 (0.012) and a=1.02 (0.008); a=1.02 wins it, and a=1.0
  // falls back to b=0.99 (0.010).
  const std::vector<double> a = {1.0, 1.02, 2.0};
  const std::vector<double> b = {0.99, 1.012, 2.5};
  const auto m = associate_greedy(a, b, 0.02);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].first, 0u);
  EXPECT_EQ(m[0].second, 0u);
  EXPECT_EQ(m[1].first, 1u);
  EXPECT_EQ(m[1].second, 1u);
}

TEST(AssociateGreedy, ToleranceIsStrictAndOffsetShiftsTheSecondList) {
  const std::vector<double> a = {10.0};
  EXPECT_TRUE(associate_greedy(a, {10.03}, 0.02).empty());
  EXPECT_EQ(associate_greedy(a, {10.03}, 0.02, -0.025).size(), 1u);
  EXPECT_TRUE(associate_greedy(a, {10.5}, 0.5).empty());  // |diff| == max_diff is rejected
}

}  // namespace
}  // namespace slamkit
