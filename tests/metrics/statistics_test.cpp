#include "eval/metrics/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slamkit::eval {
namespace {

TEST(ComputeStats, MatchesHandComputedValuesForAnEvenCount) {
  // 1 2 3 4: mean 2.5, median (2+3)/2, rmse sqrt(30/4), population std sqrt(5/4).
  const ErrorStats s = compute_stats({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
}

TEST(ComputeStats, OddCountTakesTheMiddleValueAndEmptyIsAllZero) {
  const ErrorStats s = compute_stats({0.3, 0.1, 0.2});
  EXPECT_DOUBLE_EQ(s.median, 0.2);
  EXPECT_NEAR(s.std, std::sqrt((0.01 + 0.0 + 0.01) / 3.0), 1e-15);
  const ErrorStats empty = compute_stats({});
  EXPECT_EQ(empty.count, 0u);
  EXPECT_EQ(empty.rmse, 0.0);
}

}  // namespace
}  // namespace slamkit::eval
