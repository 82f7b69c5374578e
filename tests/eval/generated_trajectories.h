#pragma once
// Trajectory files of the KITTI and EuRoC shapes, generated (deterministically) for the tests
// that compare slamkit with evo and with the KITTI devkit: their own data is not ours to copy.
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace slamkit::eval::test_files {

namespace fs = std::filesystem;

// Pseudo-random numbers in [-1, 1) from a 64-bit LCG (the same everywhere, unlike <random>'s
// distributions).
class Noise {
 public:
  double next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state_ >> 11) * 0x1p-52 - 1.0;
  }
  Eigen::Vector3d vector() {
    const double x = next(), y = next();
    return {x, y, next()};
  }

 private:
  uint64_t state_ = 48;
};

// As KITTI's own pose files print a pose: %e, 7 significant digits, so that R^T R - I is about
// 1e-7 and the tests see what evo and the devkit compute on such matrices.
inline void write_kitti_pose(std::FILE* f, const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  for (int r = 0; r < 3; ++r)
    std::fprintf(f, "%e %e %e %e%s", R(r, 0), R(r, 1), R(r, 2), p(r), r == 2 ? "\n" : " ");
}

// A KITTI-shaped drive: 600 poses (poses/NN.txt layout, camera z forward, y down) winding over
// about 850 m of gently rolling ground, a times.txt at about 10 Hz, and an estimate with heading
// drift, a 1 % scale error and noise, printed as KITTI prints its poses.
inline void write_kitti_drive(const fs::path& dir) {
  std::FILE* gt = std::fopen((dir / "gt.txt").c_str(), "w");
  std::FILE* est = std::fopen((dir / "est.txt").c_str(), "w");
  std::FILE* times = std::fopen((dir / "times.txt").c_str(), "w");
  Noise noise;
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), q = Eigen::Vector3d::Zero();
  for (int k = 0; k < 600; ++k) {
    const double s = k;
    const double yaw = 1.2 * std::sin(s / 70.0) + 0.004 * s, pitch = 0.03 * std::sin(s / 45.0);
    const double yaw_est = yaw + 2e-4 * s + 0.003 * noise.next();
    const double pitch_est = pitch + 0.002 * noise.next(), roll_est = 0.002 * noise.next();
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    const Eigen::Matrix3d R_est = (Eigen::AngleAxisd(yaw_est, Eigen::Vector3d::UnitY()) *
                                   Eigen::AngleAxisd(pitch_est, Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(roll_est, Eigen::Vector3d::UnitZ()))
                                      .toRotationMatrix();
    write_kitti_pose(gt, R, p);
    write_kitti_pose(est, R_est, q);
    std::fprintf(times, "%.9f\n", 0.1036 * s + 1e-4 * noise.next());
    const double speed = 1.4 + 0.4 * std::sin(s / 33.0);  // metres a frame
    p += speed * (R * Eigen::Vector3d::UnitZ());
    q += 1.01 * speed * (R_est * Eigen::Vector3d::UnitZ()) + 0.02 * noise.vector();
  }
  for (std::FILE* f : {gt, est, times}) std::fclose(f);
}

// An EuRoC-shaped flight: groundtruth as mav0/state_groundtruth_estimate0/data.csv (integer
// nanosecond stamps at 200 Hz with jitter, w-first quaternions, 17 columns) over 30 s, and a
// TUM estimate at 20 Hz (as evo's V102.txt) in another world frame at 0.9 scale with noise;
// its first poses come before groundtruth starts (unmatched), and some stamps are repeated.
inline void write_euroc_flight(const fs::path& dir) {
  std::FILE* gt = std::fopen((dir / "gt.csv").c_str(), "w");
  std::FILE* est = std::fopen((dir / "est.txt").c_str(), "w");
  std::fprintf(gt,
               "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], "
               "q_RS_y [], q_RS_z [], v_RS_R_x [m s^-1], v_RS_R_y [m s^-1], v_RS_R_z [m s^-1], "
               "b_w_RS_S_x [rad s^-1], b_w_RS_S_y [rad s^-1], b_w_RS_S_z [rad s^-1], "
               "b_a_RS_S_x [m s^-2], b_a_RS_S_y [m s^-2], b_a_RS_S_z [m s^-2]\n");
  Noise noise;
  const int64_t start_ns = 1403715524907143168;
  const Eigen::Quaterniond world(Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.3, 1.0).normalized()));
  const Eigen::Vector3d world_offset(4.0, -1.5, 0.3);
  for (int k = -30; k < 6000; ++k) {
    const int64_t ns = start_ns + int64_t(k) * 5000000 + int64_t(2000 * noise.next());
    const double t = double(ns - start_ns) * 1e-9;
    const Eigen::Vector3d p(2.5 * std::sin(0.31 * t), 1.8 * std::sin(0.47 * t + 0.5),
                            1.0 + 0.6 * std::sin(0.23 * t));
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.2 * t, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(0.2 * std::sin(0.5 * t), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(0.15 * std::sin(0.7 * t), Eigen::Vector3d::UnitX()));
    if (k >= 0)
      std::fprintf(gt, "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,0,0,0,0,0,0,0,0,0\n",
                   static_cast<long long>(ns), p.x(), p.y(), p.z(), q.w(), q.x(), q.y(), q.z());
    if ((k + 1000) % 10 != 3) continue;
    // About 1 ms after a groundtruth pose: the nearest one is never in doubt.
    const double stamp = double(ns) * 1e-9 + 1e-3 + 4e-4 * noise.next();
    const double drift = 0.004 * t;
    const Eigen::Quaterniond q_noise(Eigen::AngleAxisd(0.01 + drift, noise.vector().normalized()));
    const Eigen::Quaterniond q_est = (world * q * q_noise).normalized();
    const Eigen::Vector3d p_est =
        world * (0.9 * (p + Eigen::Vector3d(drift, -0.5 * drift, 0.0) + 0.01 * noise.vector())) +
        world_offset;
    // Every 50th estimated stamp is repeated with another pose, as in evo's V102.txt: evo
    // keeps both lines.
    for (int repeat = 0; repeat < ((k + 1000) % 500 == 3 ? 2 : 1); ++repeat) {
      const Eigen::Vector3d p_line = p_est + repeat * 0.05 * noise.vector();
      std::fprintf(est, "%.9f %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", stamp, p_line.x(),
                   p_line.y(), p_line.z(), q_est.x(), q_est.y(), q_est.z(), q_est.w());
    }
  }
  std::fclose(gt);
  std::fclose(est);
}

}  // namespace slamkit::eval::test_files
