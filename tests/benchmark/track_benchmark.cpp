// The benchmark (a target, not a test): on real TUM frames ($SLAMKIT_DATA fr2/desk) and on
// synthetic 600-frame `desk` and `loop` sequences rendered for the run, the front end alone
// (`slamkit track`: per-stage median milliseconds per frame, frames per second) and the whole
// pipeline (`slamkit run`: the wall time of each stage, decode to map.ply, frames per second,
// the loop pass per keyframe), and the ratio of the two wall times. Each also reports its
// process CPU time: at n threads no schedule can take less wall time than CPU / n, which
// bounds the ratio that any overlap of the stages could reach.
//   cmake --build build --target benchmark        (or: build/tests/benchmark/slamkit_benchmark)
#include <omp.h>

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

// The decode floor: every frame pair decoded on `threads` threads with nothing else running,
// wall milliseconds per frame. No pipeline can prepare frames faster.
double decode_floor_ms(const TumSequence& sequence, int threads) {
  omp_set_num_threads(threads);
  Stopwatch watch;
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < long(sequence.size()); ++k) sequence.load(size_t(k));
  return watch.lap() / double(sequence.size());
}

struct Seconds {
  double wall = 0, cpu = 0;
  int threads = 1;  // as the run used them
};

// Returns the wall and CPU seconds, decode to trajectory.
Seconds report_front_end(const std::string& name, const TumSequence& sequence, int threads) {
  Settings settings;
  settings.pipeline.threads = threads;
  CpuStopwatch cpu;
  const RunResult result = track_sequence(sequence, front_end_only(settings));
  const double cpu_seconds = cpu.lap() / 1000.0;
  const TimingSummary timing = summarise_timing(result);
  std::printf("\n%s, front end (track): %zu frames, %d thread(s)\n", name.c_str(),
              result.frames.size(), result.threads);
  std::printf("  %-12s %9s %9s %9s\n", "stage", "median", "mean", "max");
  for (const StageStats& s : timing.stages)
    std::printf("  %-12s %7.2fms %7.2fms %7.2fms\n", s.name.c_str(), s.median_ms, s.mean_ms,
                s.max_ms);
  std::printf("  tracking (all after decode) median %.2f ms/frame\n", timing.tracking_median_ms);
  std::printf("  wall: prepare %.2f s (parallel, beside tracking), track %.2f s; %.2f s in all "
              "-> %.1f frames/s; CPU %.2f s\n",
              result.seconds.prepare, result.seconds.track, result.seconds.total,
              timing.frames_per_second, cpu_seconds);
  const double floor_ms = decode_floor_ms(sequence, result.threads);
  const double end_to_end_ms = 1000 * result.seconds.total / double(result.frames.size());
  std::printf(
      "  decode floor %.2f ms/frame (decode alone on %d thread(s)); end to end %.2f "
      "ms/frame: %.2fx the floor\n",
      floor_ms, result.threads, end_to_end_ms, end_to_end_ms / floor_ms);
  return {result.seconds.total, cpu_seconds, result.threads};
}

// Returns the wall and CPU seconds, decode to map.ply.
Seconds report_pipeline(const std::string& name, const TumSequence& sequence, int threads) {
  Settings settings;
  settings.pipeline.threads = threads;
  settings.pipeline.evaluate = false;
  const fs::path out = fs::temp_directory_path() / "slamkit_benchmark_run";
  CpuStopwatch cpu;
  const RunResult result = run_batch(sequence, settings, out, name);
  const double cpu_seconds = cpu.lap() / 1000.0;
  const StageTimes& t = result.seconds;
  int local_runs = 0;
  double wait = 0;
  for (const MappingReport& r : result.keyframe_reports) {
    local_runs += r.ba_run;
    wait += r.ba_wait_ms / 1000.0;
  }
  std::printf("\n%s, whole pipeline (run): %zu frames, %zu keyframes, %d thread(s)\n",
              name.c_str(), result.frames.size(), result.map.keyframes().size(), result.threads);
  std::printf("  prepare    %6.2f s  (parallel, beside tracking)\n", t.prepare);
  std::printf("  track      %6.2f s  (with mapping; %.2f s of it waiting for local BA)\n", t.track,
              wait);
  std::printf("  local BA   %6.2f s  (%d solves beside tracking, %.1f ms each)\n", t.local_ba,
              local_runs, local_runs ? 1000 * t.local_ba / local_runs : 0.0);
  const LoopPassReport& loops = result.loop_pass;
  const double per_keyframe_ms =
      loops.keyframes ? 1000 * t.loops / double(loops.keyframes) : 0.0;
  std::printf("  loops      %6.2f s  (%.2f ms a keyframe: vocabulary of %zu words %.2f s, "
              "detection %.2f s, correction %.2f s; %zu loops)\n",
              t.loops, per_keyframe_ms, loops.vocabulary_words, loops.vocabulary_seconds,
              loops.detection_seconds, loops.correction_seconds, loops.loops.size());
  std::printf("  global BA  %6.2f s\n", t.global_ba);
  std::printf("  fusion     %6.2f s  (%zu frames -> %zu points)\n", t.fusion, result.fusion.frames,
              result.fusion.after_outlier_removal);
  std::printf("  write      %6.2f s\n", t.write);
  std::printf("  total      %6.2f s  -> %.1f frames/s, decode to map.ply; CPU %.2f s\n", t.total,
              double(result.frames.size()) / t.total, cpu_seconds);
  fs::remove_all(out);
  return {t.total, cpu_seconds, result.threads};
}

void report(const std::string& name, const TumSequence& sequence, int threads) {
  const Seconds track = report_front_end(name, sequence, threads);
  const Seconds run = report_pipeline(name, sequence, threads);
  std::printf("  run / track wall time: %.2fx\n", run.wall / track.wall);
  std::printf("  CPU: track %.2f s, run %.2f s (+%.2f s); at %d thread(s) run needs at least "
              "%.2f s, %.2fx track's wall time\n",
              track.cpu, run.cpu, run.cpu - track.cpu, run.threads, run.cpu / run.threads,
              run.cpu / run.threads / track.wall);
}

void report_synthetic(synth::Preset preset, const std::string& name, int threads) {
  const fs::path folder = fs::temp_directory_path() / ("slamkit_benchmark_" + name);
  synth::SequenceSpec spec;
  spec.preset = preset;
  spec.frames = 600;
  spec.out = folder;
  Stopwatch watch;
  synth::write_sequence(synth::make_named_scene(synth::preset_scene(preset)), spec);
  std::printf("\nrendered synthetic %s (600 frames) in %.1f s\n", name.c_str(),
              watch.lap() / 1000.0);
  report("synthetic " + name + " 600", TumSequence::open(folder), threads);
  fs::remove_all(folder);
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
  report_synthetic(synth::Preset::kDesk, "desk", threads);
  report_synthetic(synth::Preset::kLoop, "loop", threads);
  return 0;
}
