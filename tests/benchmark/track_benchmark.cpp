// The benchmark (a target, not a test): on real TUM frames ($SLAMKIT_DATA fr2/desk 50, depth
// scale 5208) and synthetic desk and loop 600 rendered for the run, or on the sequences given:
// - the front end alone, in process (`track`: per-stage median milliseconds a frame, frames per
//   second, CPU time, the decode floor);
// - the whole pipeline, `slamkit run --no-eval --no-report` in a fresh process each time (median
//   of --runs, default 3): each stage's wall and CPU time, the process's wall and CPU time, peak
//   memory and frames per second;
// - with --orbslam2 RGBD_TUM --vocabulary VOC, ORB-SLAM2's rgbd_tum on the same frames, its runs
//   interleaved with slamkit's and measured the same way, and the ratios.
//   cmake --build build --target benchmark
//   build/tests/benchmark/slamkit_benchmark [--threads N] [--runs N]
//       [--orbslam2 RGBD_TUM --vocabulary VOC] [SEQUENCE[@DEPTH_SCALE]...]
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "child_process.h"
#include "core/number_format.h"
#include "core/stopwatch.h"
#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"
#include "orbslam2_peer.h"
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

void report_front_end(const std::string& name, const TumSequence& sequence, int threads) {
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
  std::printf(
      "  wall: prepare %.2f s (parallel, beside tracking), track %.2f s; %.2f s in all "
      "-> %.1f frames/s; CPU %.2f s\n",
      result.seconds.prepare, result.seconds.track, result.seconds.total, timing.frames_per_second,
      cpu_seconds);
  const double floor_ms = decode_floor_ms(sequence, result.threads);
  const double end_to_end_ms = 1000 * result.seconds.total / double(result.frames.size());
  std::printf(
      "  decode floor %.2f ms/frame (decode alone on %d thread(s)); end to end %.2f "
      "ms/frame: %.2fx the floor\n",
      floor_ms, result.threads, end_to_end_ms, end_to_end_ms / floor_ms);
}

struct Median {
  std::vector<double> values;
  double operator()() const {
    std::vector<double> v = values;
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
  }
};

// `slamkit run --no-eval --no-report` `runs` times, each in a fresh process (as ORB-SLAM2 is
// measured), interleaved with ORB-SLAM2's runs when `peer` is given: the medians of wall time,
// CPU time and peak memory, each stage's wall and CPU time (timing.json), and the ratios.
void report_pipeline(const std::string& name, const TumSequence& sequence, int threads, int runs,
                     const std::optional<bench::OrbSlam2>& peer) {
  const fs::path work = fs::temp_directory_path() / "slamkit_benchmark_run";
  const std::vector<std::string> stages = {"track",  "loops", "global_ba", "refine",
                                           "fusion", "write", "total"};
  Median wall, cpu, rss, orb_wall, orb_cpu, orb_rss, orb_poses;
  std::map<std::string, Median> stage_wall, stage_cpu;
  nlohmann::json timing;
  for (int r = 0; r < runs; ++r) {
    fs::remove_all(work);
    fs::create_directories(work);
    const bench::ChildUsage usage = bench::run_child(
        {SLAMKIT_BINARY, "run", sequence.folder().string(), "--out", (work / "run").string(),
         "--no-eval", "--no-report", "--threads", std::to_string(threads), "--depth-scale",
         format_exact(sequence.camera().depth_scale)},
        work / "run.log", work);
    if (usage.exit_code != 0)
      throw std::runtime_error("slamkit run failed on " + name + ": see " +
                               (work / "run.log").string());
    timing = nlohmann::json::parse(std::ifstream(work / "run" / "timing.json"));
    wall.values.push_back(usage.wall_s);
    cpu.values.push_back(usage.cpu_s);
    rss.values.push_back(usage.peak_rss_mb);
    for (const std::string& s : stages) {
      stage_wall[s].values.push_back(timing["seconds"][s].get<double>());
      stage_cpu[s].values.push_back(timing["cpu_seconds"][s].get<double>());
    }
    if (!peer) continue;
    const bench::PeerRun orb = bench::run_orbslam2(*peer, sequence, work / "orbslam2");
    if (orb.usage.exit_code != 0)
      throw std::runtime_error("ORB-SLAM2 failed on " + name + ": see " +
                               (work / "orbslam2" / "log.txt").string());
    orb_wall.values.push_back(orb.usage.wall_s);
    orb_cpu.values.push_back(orb.usage.cpu_s);
    orb_rss.values.push_back(orb.usage.peak_rss_mb);
    orb_poses.values.push_back(double(orb.poses));
  }
  std::printf(
      "\n%s, whole pipeline (run --no-eval, a fresh process each time, median of %d): "
      "%zu frames, %d keyframes, %s thread(s)\n",
      name.c_str(), runs, sequence.size(), timing["keyframes"].get<int>(),
      threads ? std::to_string(threads).c_str() : "all");
  std::printf("  %-10s %8s %8s\n", "stage", "wall s", "CPU s");
  for (const std::string& s : stages)
    std::printf("  %-10s %8.2f %8.2f%s\n", s.c_str(), stage_wall[s](), stage_cpu[s](),
                s == "track" ? "  (with preparation and local BA beside it)" : "");
  std::printf("  %-10s %8.2f %8.2f  (with start and exit) peak memory %.0f MB, %.1f frames/s\n",
              "process", wall(), cpu(), rss(), double(sequence.size()) / wall());
  if (!peer) return;
  std::printf("  ORB-SLAM2  %8.2f %8.2f  peak memory %.0f MB, tracked %.0f of %zu frames\n",
              orb_wall(), orb_cpu(), orb_rss(), orb_poses(), sequence.size());
  std::printf("  slamkit / ORB-SLAM2: wall %.2fx, CPU %.2fx, peak memory %.2fx\n",
              wall() / orb_wall(), cpu() / orb_cpu(), rss() / orb_rss());
  fs::remove_all(work);
}

struct Options {
  int threads = 0;
  int runs = 3;
  std::optional<bench::OrbSlam2> peer;
  std::vector<std::string> sequences;  // FOLDER or FOLDER@DEPTH_SCALE
};

void report(const std::string& name, const TumSequence& sequence, const Options& options) {
  report_front_end(name, sequence, options.threads);
  report_pipeline(name, sequence, options.threads, options.runs, options.peer);
}

void report_synthetic(synth::Preset preset, const std::string& name, const Options& options) {
  const fs::path folder = fs::temp_directory_path() / ("slamkit_benchmark_" + name);
  synth::SequenceSpec spec;
  spec.preset = preset;
  spec.frames = 600;
  spec.out = folder;
  Stopwatch watch;
  synth::write_sequence(synth::make_named_scene(synth::preset_scene(preset)), spec);
  std::printf("\nrendered synthetic %s (600 frames) in %.1f s\n", name.c_str(),
              watch.lap() / 1000.0);
  report("synthetic " + name + " 600", TumSequence::open(folder), options);
  fs::remove_all(folder);
}

Options parse_options(int argc, char** argv) {
  Options options;
  std::optional<fs::path> rgbd_tum, vocabulary;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--threads")
      options.threads = std::stoi(value());
    else if (arg == "--runs")
      options.runs = std::max(1, std::stoi(value()));
    else if (arg == "--orbslam2")
      rgbd_tum = value();
    else if (arg == "--vocabulary")
      vocabulary = value();
    else if (arg.rfind("--", 0) == 0)
      throw std::runtime_error("unknown option " + arg);
    else
      options.sequences.push_back(arg);
  }
  if (rgbd_tum.has_value() != vocabulary.has_value())
    throw std::runtime_error("--orbslam2 RGBD_TUM and --vocabulary VOC go together");
  if (rgbd_tum) {
    for (const fs::path& p : {*rgbd_tum, *vocabulary})
      if (!fs::is_regular_file(p)) throw std::runtime_error(p.string() + ": no such file");
    options.peer = bench::OrbSlam2{*rgbd_tum, *vocabulary};
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) try {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a line at a time, also into a file
  const Options options = parse_options(argc, argv);
  if (!options.sequences.empty()) {
    for (const std::string& arg : options.sequences) {
      const size_t at = arg.rfind('@');
      SequenceOptions sequence_options;
      if (at != std::string::npos) sequence_options.depth_scale = std::stod(arg.substr(at + 1));
      const std::string folder = arg.substr(0, at);
      report(fs::path(folder).filename().string(), TumSequence::open(folder, sequence_options),
             options);
    }
    return 0;
  }
  if (const char* data = std::getenv("SLAMKIT_DATA")) {
    const fs::path fr2 = fs::path(data) / "rgbd_dataset_freiburg2_desk_first50";
    SequenceOptions freiburg2;
    freiburg2.depth_scale = 5208;  // ORB-SLAM2's Freiburg 2 correction, for both systems
    if (fs::exists(fr2)) report("fr2/desk first 50", TumSequence::open(fr2, freiburg2), options);
  } else {
    std::printf("SLAMKIT_DATA not set: skipping the real sequence\n");
  }
  report_synthetic(synth::Preset::kDesk, "desk", options);
  report_synthetic(synth::Preset::kLoop, "loop", options);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "slamkit_benchmark: %s\n", e.what());
  return 2;
}
