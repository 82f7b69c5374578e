// The same poses read from TUM, KITTI and EuRoC files give the same ATE: the readers agree on
// poses and stamps (rotation matrices and w-first quaternions included).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>

#include "eval/metrics/association.h"
#include "eval/metrics/ate.h"
#include "io/euroc_csv.h"
#include "io/kitti_poses.h"
#include "io/trajectory_io.h"
#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

// A turning helix with noise, at 30 Hz from 1000 s, stamps whole nanoseconds.
Trajectory noisy_helix(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  Trajectory t;
  for (size_t k = 0; k < n; ++k) {
    const double s = 0.05 * double(k);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = (Eigen::AngleAxisd(0.3 * s + noise(rng), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(0.1 * std::sin(s), Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    T.translation() =
        Eigen::Vector3d(std::cos(s) + noise(rng), std::sin(s) + noise(rng), 0.1 * s);
    t.push_back(1000.0 + double(33'333'333 * k) * 1e-9, T);
  }
  return t;
}

void write_kitti(const fs::path& poses, const fs::path& times, const Trajectory& t) {
  std::FILE* p = std::fopen(poses.c_str(), "w");
  std::FILE* s = std::fopen(times.c_str(), "w");
  for (size_t i = 0; i < t.size(); ++i) {
    const Eigen::Matrix<double, 3, 4> m = t.pose(i).matrix().topRows<3>();
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) std::fprintf(p, "%.17g%s", m(r, c), r == 2 && c == 3 ? "\n" : " ");
    std::fprintf(s, "%.17g\n", t.stamp(i));
  }
  std::fclose(p);
  std::fclose(s);
}

void write_euroc(const fs::path& path, const Trajectory& t) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fprintf(f, "#timestamp [ns],p_x,p_y,p_z,q_w,q_x,q_y,q_z\n");
  for (size_t i = 0; i < t.size(); ++i) {
    const long long ns = 1'000'000'000'000LL + 33'333'333LL * (long long)i;
    const Eigen::Vector3d& p = t.position(i);
    const Eigen::Quaterniond& q = t.orientation(i);
    std::fprintf(f, "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", ns, p.x(), p.y(), p.z(),
                 q.w(), q.x(), q.y(), q.z());
  }
  std::fclose(f);
}

AteResult ate_of(const Trajectory& gt, const Trajectory& est) {
  return compute_ate(gt, est, associate(gt, est, AssociationOptions{}), AteOptions{});
}

TEST(FormatsAte, KittiAndEurocFilesOfATumTrajectoryGiveTheSameAte) {
  const fs::path dir = test::temp_dir("formats_ate");
  const Trajectory gt = noisy_helix(300, 1);
  const Trajectory est_poses = noisy_helix(300, 2);
  write_tum_trajectory(dir / "est.txt", est_poses);
  write_kitti(dir / "est_kitti.txt", dir / "times.txt", est_poses);
  write_euroc(dir / "est.csv", est_poses);
  const Trajectory tum = read_tum_trajectory(dir / "est.txt").trajectory;
  const Trajectory kitti = read_kitti_poses(dir / "est_kitti.txt", dir / "times.txt").trajectory;
  const Trajectory euroc = read_euroc_csv(dir / "est.csv").trajectory;

  const AteResult a = ate_of(gt, tum);
  ASSERT_EQ(a.trans_errors.size(), 300u);
  EXPECT_GT(a.trans.rmse, 1e-3);  // the noise is measured, not zero
  for (const Trajectory* other : {&kitti, &euroc}) {
    const AteResult b = ate_of(gt, *other);
    ASSERT_EQ(b.trans_errors.size(), a.trans_errors.size());
    EXPECT_NEAR(b.trans.rmse, a.trans.rmse, 1e-12);
    EXPECT_NEAR(b.trans.max, a.trans.max, 1e-12);
    EXPECT_NEAR(b.rot_deg.rmse, a.rot_deg.rmse, 1e-9);  // acos near 0 amplifies rounding
  }
}

}  // namespace
}  // namespace slamkit::eval
