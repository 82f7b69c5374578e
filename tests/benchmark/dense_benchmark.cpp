// Dense point-to-plane alignment alone (a target, not a test), as the tracker runs it on a
// frame without enough features: the frame's surface pyramid, then the alignment with the
// previous frame's (built one frame earlier). Over the plain-corner stretch of a synthetic
// `lowtexture` sequence (32% to 72% of its frames), the guess is the previous groundtruth
// motion (a constant-velocity model). Prints milliseconds per frame, wall and process CPU
// (CPU is what a shared machine does not inflate; with 2 threads it includes OpenMP's spin
// waits), the mean CPU split into building the surfaces and aligning, at 1 and 2 threads,
// and the error of the relative motion against groundtruth.
//   build/tests/benchmark/slamkit_dense_benchmark [SEQUENCE]   (default: renders lowtexture 600)
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <vector>

#include "core/settings/settings.h"
#include "core/stopwatch.h"
#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"
#include "datasets/synth/trajectory_presets.h"
#include "io/tum_sequence.h"
#include "tracking/point_to_plane.h"
#include "tracking/surface_pyramid.h"

namespace fs = std::filesystem;
using namespace slamkit;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double mean(const std::vector<double>& v) {
  return v.empty() ? 0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

// The groundtruth pose at frame i's stamp (nearest; synthetic groundtruth has every frame).
Eigen::Isometry3d truth(const TumSequence& seq, size_t i) {
  const Trajectory& gt = *seq.groundtruth();
  size_t best = 0;
  for (size_t k = 0; k < gt.size(); ++k)
    if (std::abs(gt.stamp(k) - seq.stamp(i)) < std::abs(gt.stamp(best) - seq.stamp(i))) best = k;
  return gt.pose(best);
}

void report(const TumSequence& seq, int threads) {
  omp_set_num_threads(threads);
  const PointToPlaneSettings settings = Settings{}.tracking.point_to_plane;
  const size_t first = size_t(0.32 * double(seq.size())), last = size_t(0.72 * double(seq.size()));
  std::vector<double> wall, cpu, surfaces_cpu, err_mm;
  int iterations = 0;
  SurfacePyramid prev = make_surface_pyramid(seq.load(first).depth, seq.camera(), settings);
  Eigen::Isometry3d T_prev_curr_guess = truth(seq, first - 1).inverse() * truth(seq, first);
  for (size_t i = first + 1; i <= last; ++i) {
    const cv::Mat depth = seq.load(i).depth;
    Stopwatch wall_watch;
    CpuStopwatch cpu_watch;
    SurfacePyramid curr = make_surface_pyramid(depth, seq.camera(), settings);
    surfaces_cpu.push_back(cpu_watch.lap());
    const DenseAlignment a = point_to_plane(prev, curr, T_prev_curr_guess, cv::Rect(), settings);
    wall.push_back(wall_watch.lap());
    cpu.push_back(surfaces_cpu.back() + cpu_watch.lap());
    iterations += a.iterations;
    const Eigen::Isometry3d T_true = truth(seq, i - 1).inverse() * truth(seq, i);
    err_mm.push_back(1e3 * (T_true.inverse() * a.T_prev_curr).translation().norm());
    T_prev_curr_guess = T_true;
    prev = std::move(curr);
  }
  std::printf(
      "%d thread(s), %zu frames: wall median %.2f mean %.2f ms; CPU median %.2f mean "
      "%.2f ms (surfaces %.2f, alignment %.2f); %.2f iterations a frame; relative motion error "
      "median %.3f mm\n",
      threads, wall.size(), median(wall), mean(wall), median(cpu), mean(cpu), mean(surfaces_cpu),
      mean(cpu) - mean(surfaces_cpu), double(iterations) / double(wall.size()), median(err_mm));
}

}  // namespace

int main(int argc, char** argv) {
  fs::path folder = argc > 1 ? fs::path(argv[1]) : fs::path();
  const bool render = folder.empty();
  if (render) {
    folder = fs::temp_directory_path() / "slamkit_dense_benchmark_lowtexture600";
    synth::SequenceSpec spec;
    spec.preset = synth::Preset::kLowTexture;
    spec.frames = 600;
    spec.out = folder;
    synth::write_sequence(synth::make_named_scene(synth::preset_scene(spec.preset)), spec);
  }
  const TumSequence seq = TumSequence::open(folder);
  for (int threads : {1, 2}) report(seq, threads);
  if (render) fs::remove_all(folder);
  return 0;
}
