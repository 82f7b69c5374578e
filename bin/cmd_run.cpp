// slamkit run SEQ --out DIR: the whole batch (docs/method.md#architecture): prepare, track
// with local BA, global BA, re-anchor every frame, fuse the map (map.ply), write, evaluate with
// groundtruth.
#include <cstdio>
#include <limits>
#include <memory>

#include "bin/command.h"
#include "bin/output_folder.h"
#include "bin/report_writing.h"
#include "bin/run_summary.h"
#include "bin/sequence_options.h"
#include "eval/metrics/ate.h"
#include "eval/run/run_evaluation.h"
#include "settings/settings_yaml.h"
#include "loop/vocabulary_file.h"
#include "pipeline/run_output.h"
#include "pipeline/run_pipeline.h"

namespace slamkit::cli {
namespace {

struct RunArgs {
  std::string folder;
  std::string out;
  std::string settings_file;
  int threads = -1;
  std::optional<LostFrames> lost_frames;
  bool evaluate = true;
  bool plot = true;
  bool ascii = false;
  bool mesh = false;
  bool loops = true;
  std::string vocabulary_file;
  bool allow_out_in_sequence = false;
  bool report = true;
  SequenceOptions sequence;
};

void print_back_end_summary(const TumSequence& seq, const Settings& settings,
                            const RunResult& result) {
  int local_runs = 0, removed = 0;
  for (const MappingReport& r : result.keyframe_reports) {
    local_runs += r.ba_run;
    removed += r.ba.removed_observations;
  }
  const StageTimes& t = result.seconds;
  std::printf("map         %d keyframes (%d redundant ones culled), %d points\n",
              result.map.num_active_keyframes(), result.map.num_culled_keyframes(),
              result.map.num_good_points());
  std::printf("local BA    %d of %zu keyframes, %d outlier observations removed, %.2f s\n",
              local_runs, result.keyframe_reports.size(), removed, t.local_ba);
  const LoopPassReport& lp = result.loop_pass;
  if (lp.ran) {
    int verified = 0;
    for (const LoopDecision& d : lp.decisions) verified += d.verified;
    std::printf(
        "loops       %zu accepted of %d candidates verified (%zu judged, loops.csv); "
        "%d points fused; %.2f s (vocabulary of %zu words %.2f, detection %.2f, "
        "correction %.2f)\n",
        lp.loops.size(), verified, lp.decisions.size(), lp.fused_points, t.loops,
        lp.vocabulary_words, lp.vocabulary_seconds, lp.detection_seconds, lp.correction_seconds);
  }
  if (result.global_ba_run)
    std::printf("global BA   %d keyframes, %d points, %d iterations, %d outliers removed, %.2f s\n",
                result.global_ba.free_keyframes + result.global_ba.fixed_keyframes,
                result.global_ba.points, result.global_ba.report.iterations,
                result.global_ba.removed_observations, t.global_ba);
  if (settings.optimization.refine_frames)
    std::printf("refinement  %d of %zu frames solved again against the final map, %.2f s\n",
                result.refined_frames, result.frames.size(), t.refine);
  const FusionReport& fused = result.fusion;
  if (fused.frames > 0 && fused.method == MapMethod::kTsdf)
    std::printf(
        "fused map   %zu frames: %zu depth samples into a %.0f mm TSDF (%zu blocks, %.0f MB), "
        "%zu surface points%s, %.2f s\n",
        fused.frames, fused.raw_points, settings.map.voxel_size * 1000, fused.blocks,
        fused.volume_mb, fused.points,
        fused.triangles > 0 ? (", " + std::to_string(fused.triangles) + " triangles").c_str() : "",
        t.fusion);
  else if (fused.frames > 0)
    std::printf(
        "fused map   %zu frames: %zu points raw, %zu after the %.0f mm voxel grid, %zu after "
        "outlier removal, %.2f s\n",
        fused.frames, fused.raw_points, fused.after_voxel_grid, settings.map.voxel_size * 1000,
        fused.points, t.fusion);
  if (result.fusion.beyond_grid > 0)
    std::fprintf(stderr,
                 "warning: %zu map points lie over 2^20 voxels (10 km at 1 cm) from the origin and "
                 "were left "
                 "out of map.ply (a trajectory that flew off?)\n",
                 result.fusion.beyond_grid);
  if (seq.groundtruth() && settings.pipeline.evaluate)
    std::printf("ATE RMSE    %.2f mm as tracked, %.2f mm after the back end\n",
                1000 * eval::ate_rmse(*seq.groundtruth(), result.tracked_trajectory()),
                1000 * eval::ate_rmse(*seq.groundtruth(), result.trajectory()));
  std::printf(
      "stages      prepare %.2f s (parallel, beside tracking), track %.2f s (local BA "
      "%.2f), loops %.2f, global BA %.2f, refinement %.2f, fusion %.2f, write %.2f; total "
      "%.2f s, %.1f frames/s\n",
      t.prepare, t.track, t.local_ba, t.loops, t.global_ba, t.refine, t.fusion, t.write, t.total,
      double(result.frames.size()) / t.total);
  const StageTimes& cpu = result.cpu_seconds;
  std::printf(
      "CPU         track %.2f s (with preparation and local BA), loops %.2f, global BA "
      "%.2f, refinement %.2f, fusion %.2f, write %.2f; total %.2f s; peak memory %.0f MB\n",
      cpu.track, cpu.loops, cpu.global_ba, cpu.refine, cpu.fusion, cpu.write, cpu.total,
      result.peak_rss_mb);
}

void run(const RunArgs& args) {
  check_output_folder("--out", args.out);
  check_output_outside_sequences("--out", args.out, {args.folder}, args.allow_out_in_sequence);
  Settings settings;
  if (!args.settings_file.empty()) read_settings_yaml(args.settings_file, settings);
  if (args.threads >= 0) settings.pipeline.threads = args.threads;
  if (args.lost_frames) settings.pipeline.lost_frames = *args.lost_frames;
  if (!args.evaluate) settings.pipeline.evaluate = false;
  if (args.ascii) settings.map.binary_ply = false;
  if (args.mesh) settings.map.mesh = true;
  if (!args.loops) settings.loop.enabled = false;
  if (!args.report) settings.report.enabled = false;
  std::optional<Vocabulary> vocabulary;
  if (!args.vocabulary_file.empty()) vocabulary = load_vocabulary(args.vocabulary_file);
  const TumSequence seq = TumSequence::open(args.folder, args.sequence);

  fill_run_folder(begin_run_folder(args.out, settings), [&] {
    RunResult result;
    {
      StageProgress progress;
      result = run_batch(seq, settings, args.out, seq.folder().filename().string(),
                         std::ref(progress), vocabulary ? &*vocabulary : nullptr);
    }
    print_tracking_summary(seq, result);
    print_back_end_summary(seq, settings, result);
    if (settings.pipeline.evaluate) {
      eval::evaluate_run_folder(seq, args.out, args.plot);
      if (result.loop_pass.ran) eval::evaluate_run_loops(seq, args.out);
      if (result.fusion.frames > 0) eval::evaluate_run_map(seq, settings.map.max_depth, args.out);
    }
    std::printf("output      %s\n", args.out.c_str());
    if (result.fusion.frames > 0)
      std::printf("map         %s\n", (std::filesystem::path(args.out) / "map.ply").c_str());
    if (result.fusion.triangles > 0)
      std::printf("mesh        %s\n", (std::filesystem::path(args.out) / "mesh.ply").c_str());
    return result.seconds;
  });
  // A view of the finished folder, written after run.json says it is complete.
  if (settings.report.enabled)
    write_report_page({args.out}, std::filesystem::path(args.out) / "report.html",
                      settings.report);
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = root.add_subcommand(
      "run",
      "The whole pipeline over a TUM sequence: tracking with local BA, global BA, fused "
      "point-cloud map (map.ply), evaluation");
  cmd->add_option("sequence", args->folder, "Sequence folder (TUM layout)")->required();
  cmd->add_option("--out", args->out, "Run folder to write")->required();
  cmd->add_option("--settings", args->settings_file, "Settings YAML (over the built-in defaults)");
  cmd->add_option("--threads", args->threads, "Threads for the parallel stages (0 = all cores)")
      ->check(CLI::Range(0, std::numeric_limits<int>::max()));  // pipeline.threads' range
  cmd->add_flag("!--no-eval", args->evaluate, "Skip the evaluation against groundtruth");
  cmd->add_flag("!--no-plot", args->plot, "Evaluate without drawing the plots");
  add_lost_frames_option(cmd, args->lost_frames);
  cmd->add_flag("--ascii", args->ascii, "Write map.ply (and mesh.ply) as ASCII (default: binary)");
  cmd->add_flag("--mesh", args->mesh,
                "Also write mesh.ply: the TSDF's surface as triangles (map.mesh)");
  cmd->add_flag("!--no-loops", args->loops, "Skip the loop pass (place recognition, pose graph)");
  cmd->add_flag("!--no-report", args->report, "Do not write report.html (the run's page)");
  cmd->add_option("--vocabulary", args->vocabulary_file,
                  "Vocabulary file (slamkit vocab train, or ORB-SLAM2's ORBvoc.txt); default: "
                  "one trained on the run's keyframes");
  add_sequence_options(cmd, args->sequence);
  add_allow_out_in_sequence_flag(cmd, args->allow_out_in_sequence);
  cmd->callback([args] { run(*args); });
});

}  // namespace
}  // namespace slamkit::cli
