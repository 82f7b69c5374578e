// slamkit track SEQ --out DIR: the front end over a whole sequence (SPEC sections 1-3).
#include <cstdio>
#include <memory>

#include "bin/command.h"
#include "bin/eval_run.h"
#include "bin/sequence_options.h"
#include "core/progress.h"
#include "io/settings_yaml.h"
#include "pipeline/batch_engine.h"
#include "pipeline/run_output.h"

namespace slamkit::cli {
namespace {

struct TrackArgs {
  std::string folder;
  std::string out;
  std::string settings_file;
  int threads = -1;
  bool evaluate = true;
  SequenceOptions sequence;
};

void print_summary(const TumSequence& seq, const RunResult& result) {
  int lost = 0, keyframes = 0, svd = 0, dense = 0;
  for (const TrackedFrame& f : result.frames) {
    lost += f.lost;
    keyframes += f.keyframe;
    svd += f.solver == PoseSolver::kSvdRansac && !f.lost;
    dense += f.solver == PoseSolver::kPointToPlane && !f.lost;
  }
  const TimingSummary timing = summarise_timing(result);
  std::printf("tracked     %zu frames of %s: %d keyframes, %d lost\n", result.frames.size(),
              seq.folder().filename().string().c_str(), keyframes, lost);
  std::printf("solvers     svd_ransac %d, point_to_plane %d, motion_model %d\n", svd, dense, lost);
  for (const std::string& line : describe_failures(result)) std::printf("failure     %s\n", line.c_str());
  std::printf("speed       %.1f frames/s with %d threads; tracking median %.1f ms/frame\n",
              timing.frames_per_second, result.threads, timing.tracking_median_ms);
}

void track(const TrackArgs& args) {
  Settings settings;
  if (!args.settings_file.empty()) read_settings_yaml(args.settings_file, settings);
  if (args.threads >= 0) settings.pipeline.threads = args.threads;
  if (!args.evaluate) settings.pipeline.evaluate = false;
  const TumSequence seq = TumSequence::open(args.folder, args.sequence);

  RunResult result;
  {
    Progress progress("track", seq.size());
    result = run_batch(seq, settings, [&](size_t done, size_t) { progress.update(done); });
  }
  const std::string name = seq.folder().filename().string();
  write_run_outputs(args.out, name, seq.camera(), settings, result);
  print_summary(seq, result);
  std::printf("output      %s\n", args.out.c_str());
  if (!settings.pipeline.evaluate) return;
  if (!seq.groundtruth()) {
    std::printf("evaluation  skipped: the sequence has no groundtruth.txt\n");
    return;
  }
  // The same run as `slamkit eval all GT trajectory.txt --out RUN`: ATE, and RPE over 1 s.
  EvalArgs eval_args;
  eval_args.gt = (seq.folder() / "groundtruth.txt").string();
  eval_args.est = (std::filesystem::path(args.out) / "trajectory.txt").string();
  eval_args.out_dir = args.out;
  eval_args.system_name = "slamkit";
  eval_args.title = name;
  if (seq.duration() < 2.0) {  // too short for the benchmark's 1 s drift: consecutive frames
    eval_args.unit = "f";
    eval_args.rpe.delta = 1;
  }
  run_eval(eval_args, true, true);
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<TrackArgs>();
  CLI::App* cmd = root.add_subcommand(
      "track", "Track a TUM sequence: trajectory, keyframes, per-frame report (and ATE/RPE)");
  cmd->add_option("sequence", args->folder, "Sequence folder (TUM layout)")->required();
  cmd->add_option("--out", args->out, "Run folder to write")->required();
  cmd->add_option("--settings", args->settings_file, "Settings YAML (defaults: SPEC's)");
  cmd->add_option("--threads", args->threads, "Threads for the parallel stage (0 = all cores)");
  cmd->add_flag("!--no-eval", args->evaluate, "Skip the evaluation against groundtruth");
  add_sequence_options(cmd, args->sequence);
  cmd->callback([args] { track(*args); });
});

}  // namespace
}  // namespace slamkit::cli
