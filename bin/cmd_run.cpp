// slamkit run SEQ --out DIR: the whole batch (docs/method.md#architecture): prepare, track
// with local BA, global BA, re-anchor every frame, fuse the map (map.ply), write, evaluate with
// groundtruth.
#include <limits>
#include <memory>

#include "bin/command.h"
#include "bin/figure_options.h"
#include "bin/output_folder.h"
#include "bin/run_job.h"
#include "bin/sequence_options.h"
#include "settings/settings_yaml.h"
#include "loop/vocabulary_file.h"

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
  eval::FigureFiles figures;
  SequenceOptions sequence;
};

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
  RunJob job;
  job.settings = settings;
  job.plot = args.plot;
  job.figures = args.figures;
  job.vocabulary = vocabulary ? &*vocabulary : nullptr;
  run_into_folder(seq, args.out, job);
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
  add_figure_options(cmd, args->figures);
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
