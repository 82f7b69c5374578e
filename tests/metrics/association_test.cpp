#include "eval/metrics/association.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "core/error.h"

namespace slamkit::eval {
namespace {

Trajectory at_stamps(const std::vector<double>& stamps) {
  Trajectory t;
  for (double s : stamps) t.push_back(s, Eigen::Isometry3d::Identity());
  return t;
}

TEST(Associate, TumIsOneToOneWhileEvoLetsAPoseOfTheLongerTrajectoryServeTwice) {
  const Trajectory gt = at_stamps({1.0, 2.0, 3.0, 4.0});
  const Trajectory est = at_stamps({0.99, 1.011, 2.5});
  const auto tum = associate(gt, est, {AssociationMethod::kTum, 0.02, 0.0});
  ASSERT_EQ(tum.size(), 1u);
  EXPECT_EQ(tum[0].first, 0u);
  EXPECT_EQ(tum[0].second, 0u);  // 0.99 is 0.010 away, 1.011 is 0.011 away
  const auto evo = associate(gt, est, {AssociationMethod::kEvo, 0.02, 0.0});
  ASSERT_EQ(evo.size(), 2u);  // the estimate (3 poses) drives: both early poses take 1.0
  EXPECT_EQ(evo[0].first, 0u);
  EXPECT_EQ(evo[1].first, 0u);
  EXPECT_EQ(evo[1].second, 1u);
}

// evo's associate_trajectories loops over the trajectory with fewer poses. A thinned
// groundtruth (every 0.1 s) against an estimate with two poses near each: by hand, each
// groundtruth pose takes its exact twin, 3 pairs (looping over the estimate would give 5).
TEST(Associate, EvoLoopsOverTheTrajectoryWithFewerPoses) {
  const Trajectory gt = at_stamps({10.0, 10.1, 10.2});
  const Trajectory est = at_stamps({10.0, 10.005, 10.1, 10.105, 10.2});
  const auto evo = associate(gt, est, {AssociationMethod::kEvo, kEvoMaxDiff, 0.0});
  ASSERT_EQ(evo.size(), 3u);
  const size_t expected_est[] = {0, 2, 4};
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(evo[k].first, k);
    EXPECT_EQ(evo[k].second, expected_est[k]);
  }
  // The other way round (estimate shorter) the estimate drives, and an offset moves it.
  const auto reverse = associate(est, gt, {AssociationMethod::kEvo, kEvoMaxDiff, 0.004});
  ASSERT_EQ(reverse.size(), 3u);  // 10.0+0.004 -> 10.005 (0.001), 10.1+0.004 -> 10.105, ...
  EXPECT_EQ(reverse[0].first, 1u);
  EXPECT_EQ(reverse[1].first, 3u);
  EXPECT_EQ(reverse[2].first, 4u);
}

// evo keeps every line of a repeated stamp (--duplicate-stamps all); numpy's argmin then takes
// the first of equal stamps in the longer trajectory, whichever side of the stamp they are on.
TEST(Associate, EvoTakesTheFirstOfRepeatedStampsInTheLongerTrajectory) {
  const Trajectory gt = at_stamps({1.0, 1.0, 1.0, 2.0, 3.0});
  const Trajectory est = at_stamps({1.004, 2.0, 2.0});
  const auto evo = associate(gt, est, {AssociationMethod::kEvo, kEvoMaxDiff, 0.0});
  ASSERT_EQ(evo.size(), 3u);  // both estimated poses at 2.0 are kept and take the same pose
  EXPECT_EQ(evo[0].first, 0u);  // 1.004 -> the first 1.0 (the search lands on the last)
  EXPECT_EQ(evo[1].first, 3u);
  EXPECT_EQ(evo[2].first, 3u);
}

// The fast path (mutual best candidates first) must give the greedy rule's matching; checked
// against a brute-force transcription of associate.py on random stamps with many conflicts.
TEST(Associate, TumMatchesABruteForceGreedyOnRandomStamps) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.012, 0.012);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> g, e;
    for (int k = 0; k < 60; ++k) g.push_back(100.0 + 0.01 * k + 0.3 * jitter(rng));
    for (int k = 0; k < 45; ++k) e.push_back(100.0 + 0.013 * k + jitter(rng));
    std::sort(g.begin(), g.end());
    std::sort(e.begin(), e.end());
    // associate.py: all (diff, a, b) with diff < max_diff, sorted, taken greedily.
    std::vector<std::tuple<double, double, double, size_t, size_t>> candidates;
    for (size_t a = 0; a < g.size(); ++a)
      for (size_t b = 0; b < e.size(); ++b)
        if (std::abs(g[a] - e[b]) < 0.02)
          candidates.push_back({std::abs(g[a] - e[b]), g[a], e[b], a, b});
    std::sort(candidates.begin(), candidates.end());
    std::vector<bool> used_a(g.size()), used_b(e.size());
    std::set<std::pair<size_t, size_t>> expected;
    for (const auto& [diff, ta, tb, a, b] : candidates) {
      if (used_a[a] || used_b[b]) continue;
      used_a[a] = used_b[b] = true;
      expected.insert({a, b});
    }
    std::set<std::pair<size_t, size_t>> got;
    for (const IndexPair& p :
         associate(at_stamps(g), at_stamps(e), {AssociationMethod::kTum, 0.02, 0.0}))
      got.insert({p.first, p.second});
    EXPECT_EQ(got, expected) << "trial " << trial;
  }
}

TEST(Associate, OffsetIsAddedToEstimateStampsAndResultIsInEstimateOrder) {
  const Trajectory gt = at_stamps({10.0, 11.0, 12.0});
  const Trajectory est = at_stamps({5.0, 6.0, 7.0});
  EXPECT_TRUE(associate(gt, est, {AssociationMethod::kTum, 0.02, 0.0}).empty());
  for (auto method : {AssociationMethod::kTum, AssociationMethod::kEvo}) {
    const auto pairs = associate(gt, est, {method, 0.02, 5.0});
    ASSERT_EQ(pairs.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(pairs[k].second, k);
      EXPECT_EQ(pairs[k].first, k);
    }
  }
}

TEST(RequireEnoughPairs, MessageGivesCountsTimeRangesAndTolerance) {
  const Trajectory gt = at_stamps({100.0, 100.5, 101.0});
  const Trajectory est = at_stamps({200.0, 201.0});
  const AssociationOptions options{AssociationMethod::kTum, 0.02, 0.0};
  EXPECT_NO_THROW(require_enough_pairs(2, gt, est, "gt.txt", "est.txt", options));
  try {
    require_enough_pairs(1, gt, est, "gt.txt", "est.txt", options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("only 1 estimated pose(s) matched"), std::string::npos) << m;
    EXPECT_NE(m.find("within 0.02 s"), std::string::npos) << m;
    EXPECT_NE(m.find("gt.txt has 3 poses over 100.000000 .. 101.000000"), std::string::npos) << m;
    EXPECT_NE(m.find("est.txt has 2 poses over 200.000000 .. 201.000000"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace slamkit::eval
