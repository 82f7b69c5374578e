// slamkit track SEQ --out DIR: the front end over a whole sequence (features, matching and
// pose, keyframes: docs/method.md), without the back end's bundle adjustments and map
// (`slamkit run` runs everything).
#include <limits>
#include <memory>

#include "bin/command.h"
#include "bin/figure_options.h"
#include "bin/output_folder.h"
#include "bin/run_job.h"
#include "bin/sequence_options.h"
#include "settings/settings_yaml.h"
#include "pipeline/run_pipeline.h"

namespace slamkit::cli {
namespace {

struct TrackArgs {
  std::string folder;
  std::string out;
  std::string settings_file;
  int threads = -1;
  std::optional<LostFrames> lost_frames;
  bool evaluate = true;
  bool plot = true;
  eval::FigureFiles figures;
  bool allow_out_in_sequence = false;
  SequenceOptions sequence;
};

void track(const TrackArgs& args) {
  check_output_folder("--out", args.out);
  check_output_outside_sequences("--out", args.out, {args.folder}, args.allow_out_in_sequence);
  Settings settings;
  if (!args.settings_file.empty()) read_settings_yaml(args.settings_file, settings);
  if (args.threads >= 0) settings.pipeline.threads = args.threads;
  if (args.lost_frames) settings.pipeline.lost_frames = *args.lost_frames;
  if (!args.evaluate) settings.pipeline.evaluate = false;
  const TumSequence seq = TumSequence::open(args.folder, args.sequence);
  RunJob job;
  job.settings = front_end_only(settings);
  job.back_end = false;
  job.plot = args.plot;
  job.figures = args.figures;
  run_into_folder(seq, args.out, job);
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<TrackArgs>();
  CLI::App* cmd = root.add_subcommand(
      "track",
      "Track a TUM sequence with the front end alone: trajectory, keyframes, per-frame report "
      "(and ATE/RPE)");
  cmd->add_option("sequence", args->folder, "Sequence folder (TUM layout)")->required();
  cmd->add_option("--out", args->out, "Run folder to write")->required();
  cmd->add_option("--settings", args->settings_file, "Settings YAML (over the built-in defaults)");
  cmd->add_option("--threads", args->threads, "Threads for the parallel stage (0 = all cores)")
      ->check(CLI::Range(0, std::numeric_limits<int>::max()));  // pipeline.threads' range
  cmd->add_flag("!--no-eval", args->evaluate, "Skip the evaluation against groundtruth");
  cmd->add_flag("!--no-plot", args->plot, "Evaluate without drawing the plots");
  add_figure_options(cmd, args->figures);
  add_lost_frames_option(cmd, args->lost_frames);
  add_sequence_options(cmd, args->sequence);
  add_allow_out_in_sequence_flag(cmd, args->allow_out_in_sequence);
  cmd->callback([args] { track(*args); });
});

}  // namespace
}  // namespace slamkit::cli
