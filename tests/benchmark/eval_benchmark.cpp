// Evaluation on a million-pose trajectory: writes a groundtruth and an estimate of 1,000,000
// poses each (100 Hz, about 83 MB each) into a temporary folder, then times reading both,
// association, ATE and RPE (as `slamkit eval all --no-plot` does them) and prints the seconds
// per stage and the peak resident memory. Target: under 2 s and 300 MB in all.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include "eval/metrics/association.h"
#include "eval/metrics/ate.h"
#include "eval/metrics/rpe.h"
#include "io/trajectory_io.h"

namespace {

namespace fs = std::filesystem;
using slamkit::Trajectory;
using Clock = std::chrono::steady_clock;

// A circle with a slow vertical wave, turning with the motion; `noise` metres of jitter.
void write_file(const fs::path& path, size_t n, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> jitter(0.0, noise);
  FILE* out = std::fopen(path.c_str(), "w");
  std::fprintf(out, "# timestamp tx ty tz qx qy qz qw\n");
  for (size_t k = 0; k < n; ++k) {
    const double s = 0.001 * double(k);
    std::fprintf(out, "%.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f\n", 1305031102.0 + 0.01 * double(k),
                 std::cos(s) + jitter(rng), std::sin(s) + jitter(rng), 0.1 * std::sin(3 * s), 0.0,
                 0.0, std::sin(s / 2), std::cos(s / 2));
  }
  std::fclose(out);
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main() {
  constexpr size_t kPoses = 1000000;
  const fs::path dir = fs::temp_directory_path() / "slamkit_eval_benchmark";
  fs::create_directories(dir);
  const fs::path gt_path = dir / "groundtruth.txt", est_path = dir / "estimate.txt";
  std::printf("writing 2 x %zu poses to %s ...\n", kPoses, dir.c_str());
  write_file(gt_path, kPoses, 0.0, 1);
  write_file(est_path, kPoses, 0.01, 2);
  std::printf("file size     %.1f MB each\n", double(fs::file_size(est_path)) / 1e6);

  const auto start = Clock::now();
  auto t = Clock::now();
  const Trajectory gt = slamkit::read_tum_trajectory(gt_path).trajectory;
  const Trajectory est = slamkit::read_tum_trajectory(est_path).trajectory;
  std::printf("read          %.3f s\n", seconds_since(t));
  t = Clock::now();
  const auto pairs = slamkit::eval::associate(gt, est, {});
  std::printf("associate     %.3f s (%zu pairs)\n", seconds_since(t), pairs.size());
  t = Clock::now();
  {  // released before RPE, as `slamkit eval all` does once it has written the ATE files
    const auto ate = slamkit::eval::compute_ate(gt, est, pairs, {});
    std::printf("ate           %.3f s (rmse %.6f m)\n", seconds_since(t), ate.trans.rmse);
  }
  t = Clock::now();
  const auto rpe = slamkit::eval::compute_rpe(gt, est, pairs, {});
  std::printf("rpe           %.3f s (%zu pairs, rmse %.6f m)\n", seconds_since(t), rpe.pairs.size(),
              rpe.trans.rmse);
  std::printf("total         %.3f s\n", seconds_since(start));

  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("peak RSS      %.1f MB (ru_maxrss)\n", double(usage.ru_maxrss) / 1024.0);
  fs::remove_all(dir);
  return 0;
}
