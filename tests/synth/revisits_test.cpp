#include "datasets/synth/revisits.h"

#include <gtest/gtest.h>

#include <vector>

namespace slamkit::synth {
namespace {

Eigen::Isometry3d pose(double x, double yaw_deg = 0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return T;
}

// Out along x in steps of 0.3 m to 2.4 m (frames 0..8), back to 0 (frames 9..16), then two
// turns on the spot at the start: 45 deg (frame 17) and 20 deg (frame 18).
std::vector<Eigen::Isometry3d> out_and_back() {
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i <= 8; ++i) poses.push_back(pose(0.3 * i));
  for (int i = 7; i >= 0; --i) poses.push_back(pose(0.3 * i));
  poses.push_back(pose(0, 45));
  poses.push_back(pose(0, 20));
  return poses;
}

TEST(Revisits, TheWayBackRevisitsTheWayOutOnlyWhereTheCameraHadLeft) {
  // Frame j on the way back revisits the outward frames within 0.3 m of it (0.5 m allowed)
  // that the camera had left by more than 1 m: those up to 1.2 m out (frames 0..4).
  const std::vector<RevisitRange> expected = {
      {11, 4, 4},  // at 1.5 m: frame 4 (1.2 m); frame 5 (1.5 m) never left by 1 m
      {12, 3, 4},  // at 1.2 m
      {13, 2, 4},  // at 0.9 m
      {14, 1, 3},  // at 0.6 m
      {15, 0, 2},  // at 0.3 m
      {16, 0, 1},  // at the start
      {18, 0, 1},  // at the start turned 20 deg; frame 17's 45 deg is too far round
  };
  EXPECT_EQ(true_revisits(out_and_back()), expected);
}

TEST(Revisits, CriteriaAreTheDistanceAngleAndExcursionGiven) {
  RevisitCriteria strict;
  strict.max_distance_m = 0.1;  // only the same spot
  strict.max_angle_deg = 10;    // frame 18 no longer counts
  EXPECT_EQ(true_revisits(out_and_back(), strict),
            (std::vector<RevisitRange>{{12, 4, 4}, {13, 3, 3}, {14, 2, 2}, {15, 1, 1}, {16, 0, 0}}));
  RevisitCriteria far;
  far.min_excursion_m = 3;  // the camera never went 3 m away
  EXPECT_TRUE(true_revisits(out_and_back(), far).empty());
}

TEST(Revisits, ACameraThatNeverLeavesRevisitsNothing) {
  std::vector<Eigen::Isometry3d> hovering;
  for (int i = 0; i < 100; ++i) hovering.push_back(pose(0.4 * std::sin(i * 0.3), 10 * std::cos(i)));
  EXPECT_TRUE(true_revisits(hovering).empty());
  EXPECT_TRUE(true_revisits({}).empty());
}

}  // namespace
}  // namespace slamkit::synth
