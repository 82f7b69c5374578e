#include "eval/association.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace slamkit::eval {
namespace {

Trajectory at_stamps(const std::vector<double>& stamps) {
  Trajectory t;
  for (double s : stamps) t.push_back(s, Eigen::Isometry3d::Identity());
  return t;
}

TEST(Associate, TumIsOneToOneWhileEvoLetsAGroundtruthPoseServeTwice) {
  const Trajectory gt = at_stamps({1.0, 2.0});
  const Trajectory est = at_stamps({0.99, 1.011, 2.5});
  const auto tum = associate(gt, est, {AssociationMethod::kTum, 0.02, 0.0});
  ASSERT_EQ(tum.size(), 1u);
  EXPECT_EQ(tum[0].first, 0u);
  EXPECT_EQ(tum[0].second, 0u);  // 0.99 is 0.010 away, 1.011 is 0.011 away
  const auto evo = associate(gt, est, {AssociationMethod::kEvo, 0.02, 0.0});
  ASSERT_EQ(evo.size(), 2u);
  EXPECT_EQ(evo[0].first, 0u);
  EXPECT_EQ(evo[1].first, 0u);
  EXPECT_EQ(evo[1].second, 1u);
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
