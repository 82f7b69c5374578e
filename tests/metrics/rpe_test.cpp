#include "eval/metrics/rpe.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "eval/metrics/alignment.h"
#include "eval/metrics/association.h"

namespace slamkit::eval {
namespace {

// Groundtruth at 10 Hz on a curve, turning.
Trajectory curve(size_t n = 60, double rate = 10.0) {
  Trajectory t;
  for (size_t k = 0; k < n; ++k) {
    const double s = double(k) / rate;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() =
        Eigen::AngleAxisd(0.4 * s, Eigen::Vector3d(0.2, 0.3, 1).normalized()).toRotationMatrix();
    T.translation() = Eigen::Vector3d(s, 0.5 * s * s, 0.1 * s);
    t.push_back(100.0 + s, T);
  }
  return t;
}

// The estimate composes every groundtruth step with the same extra motion D:
// P_k = P_{k-1} (Q_{k-1}^-1 Q_k) D.
Trajectory with_step_error(const Trajectory& gt, const Eigen::Isometry3d& D) {
  Trajectory est;
  Eigen::Isometry3d P = gt[0].T_w_c;
  est.push_back(gt[0].stamp, P);
  for (size_t k = 1; k < gt.size(); ++k) {
    P = P * (gt[k - 1].T_w_c.inverse() * gt[k].T_w_c) * D;
    est.push_back(gt[k].stamp, P);
  }
  return est;
}

RpeResult rpe_of(const Trajectory& gt, const Trajectory& est, RpeOptions o) {
  return compute_rpe(gt, est, associate(gt, est, {}), o);
}

TEST(Rpe, KnownPerStepTranslationErrorInBothConventions) {
  const Trajectory gt = curve();
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  D.translation() = Eigen::Vector3d(0.006, -0.008, 0.0);  // |d| = 0.01 m per step
  const Trajectory est = with_step_error(gt, D);

  RpeOptions o;
  o.delta = 1;
  o.unit = DeltaUnit::kFrames;
  const RpeResult tum = rpe_of(gt, est, o);
  // i = 0..n-1 with j = i + 1, minus the pairs whose j is the last pose (i = n-2, n-1).
  EXPECT_EQ(tum.pairs.size(), gt.size() - 2);
  EXPECT_NEAR(tum.trans.min, 0.01, 1e-12);
  EXPECT_NEAR(tum.trans.max, 0.01, 1e-12);
  EXPECT_NEAR(tum.rot_deg.max, 0.0, 1e-5);

  o.convention = RpeConvention::kEvo;
  const RpeResult evo = rpe_of(gt, est, o);
  EXPECT_EQ(evo.pairs.size(), gt.size() - 1);  // evo keeps the last pair
  EXPECT_NEAR(evo.trans.rmse, 0.01, 1e-12);
}

TEST(Rpe, KnownPerStepRotationErrorOverOneSecond) {
  const Trajectory gt = curve();
  Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
  // About the groundtruth's own turning axis, so the rotations commute and add up exactly.
  D.linear() = Eigen::AngleAxisd(0.2 * M_PI / 180.0, Eigen::Vector3d(0.2, 0.3, 1).normalized())
                   .toRotationMatrix();
  const Trajectory est = with_step_error(gt, D);
  const RpeResult r = rpe_of(gt, est, RpeOptions{});  // 1 s = 10 steps of 0.2 deg
  EXPECT_NEAR(r.rot_deg.min, 2.0, 1e-6);
  EXPECT_NEAR(r.rot_deg.max, 2.0, 1e-6);
  // Poses 0..59 over 5.9 s: i with t_i + 1 s before the last pose, i.e. i = 0..48.
  EXPECT_EQ(r.pairs.size(), 49u);
  EXPECT_DOUBLE_EQ(r.pairs.front().stamp_est_j, gt[10].stamp);
}

TEST(Rpe, PairsFarFromGroundtruthAreDroppedAndTooFewIsAnError) {
  const Trajectory gt = curve();
  // Estimate poses 3 groundtruth intervals away from any groundtruth pose are dropped
  // (limit: twice the median groundtruth interval).
  Trajectory est;
  for (size_t k = 0; k < gt.size(); ++k)
    est.push_back(gt[k].stamp + (k >= 20 && k < 40 ? 10.0 : 0.0) + (k >= 40 ? 20.0 : 0.0),
                  gt[k].T_w_c);
  RpeOptions o;
  o.unit = DeltaUnit::kFrames;
  const RpeResult r = rpe_of(gt, est, o);
  EXPECT_EQ(r.pairs.size(), 19u);  // only i = 0..18 have both poses within groundtruth
  EXPECT_LT(r.trans.max, 1e-12);

  Trajectory far;
  for (size_t k = 0; k < 10; ++k) far.push_back(500.0 + k, gt[k].T_w_c);
  try {
    rpe_of(gt, far, RpeOptions{});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("RPE found 0 valid pose pair(s)"), std::string::npos)
        << e.what();
  }
}

TEST(Rpe, EvoFramesUsesConsecutiveWindowsUnlessAllPairs) {
  const Trajectory gt = curve(21);
  RpeOptions o;
  o.convention = RpeConvention::kEvo;
  o.unit = DeltaUnit::kFrames;
  o.delta = 5;
  EXPECT_EQ(rpe_of(gt, gt, o).pairs.size(), 4u);  // (0,5) (5,10) (10,15) (15,20)
  o.all_pairs = true;
  EXPECT_EQ(rpe_of(gt, gt, o).pairs.size(), 16u);  // (i, i+5) for i = 0..15
}

// Poses along x at the given positions (path length = position), one a second.
Trajectory along_x(const std::vector<double>& xs) {
  Trajectory t;
  for (size_t k = 0; k < xs.size(); ++k) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation().x() = xs[k];
    t.push_back(double(k), T);
  }
  return t;
}

std::vector<std::pair<double, double>> pair_stamps(const RpeResult& r) {
  std::vector<std::pair<double, double>> out;
  for (const RpePair& p : r.pairs) out.push_back({p.stamp_est_i, p.stamp_est_j});
  return out;
}

// evo's filter_pairs_by_path(all_pairs=True), worked by hand with delta 1 m, tol 0.1 m on path
// positions 0, 0.25, 0.5, 1.0625, 1.25, 2 (exact binary fractions):
//   i=0: distances 0.25 0.5 1.0625 1.25 2 -> 1.0625 (off 0.0625) -> (0,3)
//   i=1: 0.25 0.8125 1 1.75 -> 1 -> (1,4);  i=2: 0.5625 0.75 1.5 -> 0.75 is off 0.25 -> none
//   i=3: 0.1875 0.9375 -> (3,5);  i=4: 0.75 -> none
TEST(RpeEvo, AllPairsInMetresTakeTheClosestPathDistanceWithinTheTolerance) {
  const Trajectory t = along_x({0, 0.25, 0.5, 1.0625, 1.25, 2.0});
  RpeOptions o;
  o.convention = RpeConvention::kEvo;
  o.unit = DeltaUnit::kMetres;
  o.all_pairs = true;
  const RpeResult r = compute_rpe(t, t, associate(t, t, {AssociationMethod::kEvo, 0.01, 0}), o);
  const std::vector<std::pair<double, double>> expected = {{0, 3}, {1, 4}, {3, 5}};
  EXPECT_EQ(pair_stamps(r), expected);
  o.rel_delta_tol = 0.3;  // 0.3 m now admits i=2 (0.75) and i=4 (0.75)
  EXPECT_EQ(compute_rpe(t, t, associate(t, t, {AssociationMethod::kEvo, 0.01, 0}), o).pairs.size(),
            5u);
}

// Degree windows accumulate the angle between neighbouring poses (evo since its pull request 426): a camera
// turning 10 deg about z and back, six poses. Hand count with delta 19 deg: 10 + 10 >= 19 at
// pose 2, again at pose 4, then only 10 -> pairs (0,2), (2,4). Absolute rotation vectors (the
// old rule) would see no accumulated motion between 0 and 2.
TEST(RpeEvo, DegreeWindowsAccumulateRelativeAnglesFromThePreviousPose) {
  Trajectory t;
  for (int k = 0; k < 6; ++k) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(k % 2 ? 10.0 * M_PI / 180.0 : 0.0, Eigen::Vector3d::UnitZ())
                     .toRotationMatrix();
    T.translation() = Eigen::Vector3d(0.1 * k, 0.02 * k * k, 0);
    t.push_back(double(k), T);
  }
  RpeOptions o;
  o.convention = RpeConvention::kEvo;
  o.unit = DeltaUnit::kDegrees;
  o.delta = 19;
  const auto pairs = associate(t, t, {AssociationMethod::kEvo, 0.01, 0});
  const std::vector<std::pair<double, double>> expected = {{0, 2}, {2, 4}};
  EXPECT_EQ(pair_stamps(compute_rpe(t, t, pairs, o)), expected);
  // All pairs: the direct angle between the poses within 10% of delta; delta 10 deg finds
  // every (even, odd) pair: (0,1) (0,3) (0,5) (1,2) (1,4) (2,3) (2,5) (3,4) (4,5).
  o.all_pairs = true;
  o.delta = 10;
  EXPECT_EQ(compute_rpe(t, t, pairs, o).pairs.size(), 9u);
  o.delta = 181;
  EXPECT_THROW(compute_rpe(t, t, pairs, o), std::invalid_argument);
  // The same windows and pairs in radians (evo's --delta_unit r).
  o.unit = DeltaUnit::kRadians;
  o.all_pairs = false;
  o.delta = 19 * M_PI / 180;
  EXPECT_EQ(pair_stamps(compute_rpe(t, t, pairs, o)), expected);
  o.all_pairs = true;
  o.delta = 10 * M_PI / 180;
  EXPECT_EQ(compute_rpe(t, t, pairs, o).pairs.size(), 9u);
  o.delta = 3.2;
  EXPECT_THROW(compute_rpe(t, t, pairs, o), std::invalid_argument);
}

// evo_rpe -as scales the estimate before RPE, and metre windows measure the scaled path. The
// groundtruth moves 0.125 m a step along x, the estimate half that (scale 2). Delta 0.95 m:
// on the scaled estimate a window is 8 steps (poses 8, 16, ..., 48 -> 5 pairs, error 0); on
// the raw estimate 16 steps (16, 32, 48 -> 2 pairs), each 2 m of groundtruth against 1 m of
// estimate: error 1 m.
TEST(RpeEvo, Sim3ScaleIsAppliedBeforeChoosingPairsAndMeasuring) {
  std::vector<double> x_gt, x_est;
  for (int k = 0; k <= 48; ++k) {
    x_gt.push_back(0.125 * k);
    x_est.push_back(0.0625 * k);
  }
  const Trajectory gt = along_x(x_gt), est = along_x(x_est);
  const auto pairs = associate(gt, est, {AssociationMethod::kEvo, 0.01, 0});
  RpeOptions o;
  o.convention = RpeConvention::kEvo;
  o.unit = DeltaUnit::kMetres;
  o.delta = 0.95;
  const RpeResult raw = compute_rpe(gt, est, pairs, o);
  ASSERT_EQ(raw.pairs.size(), 2u);
  EXPECT_NEAR(raw.trans.max, 1.0, 1e-12);
  EXPECT_NEAR(raw.trans.min, 1.0, 1e-12);

  o.scale = align(gt, est, pairs, AlignMethod::kSim3).scale;
  EXPECT_NEAR(o.scale, 2.0, 1e-12);
  const RpeResult scaled = compute_rpe(gt, est, pairs, o);
  const std::vector<std::pair<double, double>> expected = {
      {8, 16}, {16, 24}, {24, 32}, {32, 40}, {40, 48}};
  EXPECT_EQ(pair_stamps(scaled), expected);
  EXPECT_LT(scaled.trans.max, 1e-12);
}

TEST(FindClosestIndex, ReproducesTheScriptsBinarySearch) {
  const std::vector<double> L = {0.0, 1.0, 2.0, 3.0};
  EXPECT_EQ(find_closest_index(L, 2.0), 2u);
  EXPECT_EQ(find_closest_index(L, 1.4), 1u);
  EXPECT_EQ(find_closest_index(L, 1.5), 2u);  // a tie goes to the first element visited
  EXPECT_EQ(find_closest_index(L, -5.0), 0u);
  EXPECT_EQ(find_closest_index(L, 99.0), 3u);
}

}  // namespace
}  // namespace slamkit::eval
