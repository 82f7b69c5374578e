// The benchmark's own numbers (evaluate_ate.py / evaluate_rpe.py, $SLAMKIT_DATA/README.md)
// for real systems' trajectories, reproduced to the printed digits.
#include <gtest/gtest.h>

#include "eval/metrics/association.h"
#include "eval/metrics/ate.h"
#include "eval/metrics/rpe.h"
#include "io/trajectory_io.h"
#include "support/test_data.h"

namespace slamkit::eval {
namespace {

struct Reference {
  const char* groundtruth;
  const char* estimate;
  size_t ate_pairs;
  double rmse, mean, median, std, min, max;
  size_t rpe_pairs;
  double rpe_trans_rmse, rpe_rot_rmse_deg;
};

void check(const Reference& ref, const std::filesystem::path& gt_path,
           const std::filesystem::path& est_path) {
  const Trajectory gt = read_tum_trajectory(gt_path).trajectory;
  const Trajectory est = read_tum_trajectory(est_path).trajectory;

  const auto pairs = associate(gt, est, AssociationOptions{});
  const AteResult ate = compute_ate(gt, est, pairs, AteOptions{});
  EXPECT_EQ(ate.trans.count, ref.ate_pairs);
  constexpr double kMetres = 5e-7;  // equal when rounded to the printed 6 decimals
  EXPECT_NEAR(ate.trans.rmse, ref.rmse, kMetres);
  EXPECT_NEAR(ate.trans.mean, ref.mean, kMetres);
  EXPECT_NEAR(ate.trans.median, ref.median, kMetres);
  EXPECT_NEAR(ate.trans.std, ref.std, kMetres);
  EXPECT_NEAR(ate.trans.min, ref.min, kMetres);
  EXPECT_NEAR(ate.trans.max, ref.max, kMetres);

  const RpeResult rpe = compute_rpe(gt, est, pairs, RpeOptions{});
  EXPECT_EQ(rpe.pairs.size(), ref.rpe_pairs);
  EXPECT_NEAR(rpe.trans.rmse, ref.rpe_trans_rmse, kMetres);
  EXPECT_NEAR(rpe.rot_deg.rmse, ref.rpe_rot_rmse_deg, 1e-4);
}

TEST(BenchmarkReference, Fr1XyzOrbSlam2) {
  SLAMKIT_REQUIRE_DATA(gt, "trajectories/fr1_xyz/groundtruth.txt");
  SLAMKIT_REQUIRE_DATA(est, "trajectories/fr1_xyz/orbslam2_rgbd.txt");
  check({"", "", 790, 0.009820, 0.008221, 0.007090, 0.005372, 0.000412, 0.035857, 757, 0.015849,
         0.977350},
        gt, est);
}

TEST(BenchmarkReference, Fr1XyzRgbdSlam) {
  SLAMKIT_REQUIRE_DATA(gt, "trajectories/fr1_xyz/groundtruth.txt");
  SLAMKIT_REQUIRE_DATA(est, "trajectories/fr1_xyz/rgbdslam.txt");
  check({"", "", 786, 0.013473, 0.012029, 0.011176, 0.006068, 0.000939, 0.034727, 753, 0.021217,
         0.934480},
        gt, est);
}

TEST(BenchmarkReference, Fr2DeskOrbSlam) {
  SLAMKIT_REQUIRE_DATA(gt, "trajectories/fr2_desk/groundtruth.txt");
  SLAMKIT_REQUIRE_DATA(est, "trajectories/fr2_desk/orbslam.txt");
  check({"", "", 2223, 0.008144, 0.007514, 0.007432, 0.003140, 0.000332, 0.024329, 1998, 0.007161,
         0.455005},
        gt, est);
}

}  // namespace
}  // namespace slamkit::eval
