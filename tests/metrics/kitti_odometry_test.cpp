// The KITTI devkit's metric on hand-worked cases: straight 1 m steps along x, 1000 frames.
#include "eval/metrics/kitti_odometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slamkit::eval {
namespace {

std::vector<Eigen::Isometry3d> straight_line(size_t n, double step, double yaw_per_frame = 0) {
  std::vector<Eigen::Isometry3d> poses;
  for (size_t k = 0; k < n; ++k) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(yaw_per_frame * double(k), Eigen::Vector3d::UnitZ()).matrix();
    T.translation() = Eigen::Vector3d(step * double(k), 0, 0);
    poses.push_back(T);
  }
  return poses;
}

// A segment of nominal length L from frame f ends at f + L + 1: the devkit takes the first
// frame whose distance exceeds L strictly, and frame f + L is exactly L away.
size_t segments_of(double length) { return size_t((998 - length) / 10) + 1; }

TEST(KittiOdometry, ConstantScaleErrorGivesItsPercentOverTheSegmentsTrueLength) {
  const auto gt = straight_line(1000, 1.0);
  const auto est = straight_line(1000, 1.01);  // 1 % too long
  const KittiOdometryResult r = compute_kitti_odometry(gt, est);
  ASSERT_EQ(r.lengths.size(), 8u);
  double sum_pct = 0;
  size_t count = 0;
  for (const KittiLengthError& l : r.lengths) {
    // |t_E| = 0.01 (L + 1) m over L m.
    EXPECT_EQ(l.segments, segments_of(l.length_m)) << l.length_m;
    EXPECT_NEAR(l.trans_pct, (l.length_m + 1) / l.length_m, 1e-9) << l.length_m;
    EXPECT_NEAR(l.rot_deg_per_m, 0.0, 1e-12);
    sum_pct += double(l.segments) * (l.length_m + 1) / l.length_m;
    count += l.segments;
  }
  EXPECT_EQ(r.segments.size(), count);
  EXPECT_EQ(r.segments.front().first, 0u);
  EXPECT_EQ(r.segments.front().last, 101u);
  EXPECT_EQ(r.segments[1].length_m, 200.0);
  EXPECT_EQ(r.segments[8].first, 10u);  // the next start, 10 frames on
  EXPECT_NEAR(r.trans_pct, sum_pct / double(count), 1e-9);
}

TEST(KittiOdometry, ConstantYawDriftGivesItsAngleOverLength) {
  const double drift = 1e-4;  // rad per frame (per metre here)
  const auto gt = straight_line(1000, 1.0);
  const auto est = straight_line(1000, 1.0, drift);
  const KittiOdometryResult r = compute_kitti_odometry(gt, est);
  ASSERT_EQ(r.lengths.size(), 8u);
  for (const KittiLengthError& l : r.lengths)
    EXPECT_NEAR(l.rot_deg_per_m, drift * (l.length_m + 1) / l.length_m * 180.0 / M_PI, 1e-9)
        << l.length_m;
}

TEST(KittiOdometry, ExactEstimateHasNoErrorAndShortPathsNoSegment) {
  const auto gt = straight_line(1000, 1.0);
  const KittiOdometryResult exact = compute_kitti_odometry(gt, gt);
  EXPECT_EQ(exact.trans_pct, 0.0);
  EXPECT_EQ(exact.rot_deg_per_m, 0.0);
  // 100 m exactly is not more than 100 m: no segment at all.
  const KittiOdometryResult short_path =
      compute_kitti_odometry(straight_line(101, 1.0), straight_line(101, 1.0));
  EXPECT_TRUE(short_path.segments.empty());
  EXPECT_TRUE(short_path.lengths.empty());
  EXPECT_EQ(short_path.path_m, 100.0);
  EXPECT_EQ(exact.path_m, 999.0);
}

}  // namespace
}  // namespace slamkit::eval
