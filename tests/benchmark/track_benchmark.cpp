// The tracking benchmark (a target, not a test): per-stage median milliseconds per frame and
// frames per second of `slamkit track`'s engine on real TUM frames ($SLAMKIT_DATA fr2/desk)
// and on a synthetic 600-frame `desk` sequence rendered for the run.
//   cmake --build build --target benchmark        (or: build/tests/benchmark/slamkit_benchmark)
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/stopwatch.h"
#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"
#include "pipeline/batch_engine.h"
#include "pipeline/run_output.h"
#include "pipeline/run_pipeline.h"

namespace fs = std::filesystem;
using namespace slamkit;

namespace {

void report(const std::string& name, const TumSequence& sequence, int threads) {
  Settings settings;
  settings.pipeline.threads = threads;
  const RunResult result = track_sequence(sequence, front_end_only(settings));
  const TimingSummary timing = summarise_timing(result);
  std::printf("\n%s: %zu frames, %d thread(s)\n", name.c_str(), result.frames.size(),
              result.threads);
  std::printf("  %-12s %9s %9s %9s\n", "stage", "median", "mean", "max");
  for (const StageStats& s : timing.stages)
    std::printf("  %-12s %7.2fms %7.2fms %7.2fms\n", s.name.c_str(), s.median_ms, s.mean_ms,
                s.max_ms);
  std::printf("  tracking (all after decode) median %.2f ms/frame\n", timing.tracking_median_ms);
  std::printf("  wall: prepare %.2f s (parallel, beside tracking), track %.2f s; %.2f s in all "
              "-> %.1f frames/s\n",
              result.seconds.prepare, result.seconds.track, result.seconds.total,
              timing.frames_per_second);
}

}  // namespace

int main(int argc, char** argv) {
  const int threads = argc > 1 ? std::atoi(argv[1]) : 0;
  if (const char* data = std::getenv("SLAMKIT_DATA")) {
    const fs::path fr2 = fs::path(data) / "rgbd_dataset_freiburg2_desk_first50";
    if (fs::exists(fr2)) report("fr2/desk first 50", TumSequence::open(fr2), threads);
  } else {
    std::printf("SLAMKIT_DATA not set: skipping the real sequence\n");
  }
  const fs::path synthetic = fs::temp_directory_path() / "slamkit_benchmark_desk600";
  synth::SequenceSpec spec;
  spec.preset = synth::Preset::kDesk;
  spec.frames = 600;
  spec.out = synthetic;
  Stopwatch watch;
  synth::write_sequence(synth::make_furnished_room(), spec);
  std::printf("\nrendered synthetic desk (600 frames) in %.1f s\n", watch.lap() / 1000.0);
  report("synthetic desk 600", TumSequence::open(synthetic), threads);
  fs::remove_all(synthetic);
  return 0;
}
