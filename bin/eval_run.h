#pragma once
// The evaluation run behind `slamkit eval ate|rpe|all`, also used by `slamkit track` when the
// sequence has groundtruth: read both files, associate, compute, write, summarise, plot.
#include <string>

#include "eval/rpe.h"

namespace slamkit::cli {

// Options of `eval ate`, `eval rpe` and `eval all` (each registers the ones it uses).
struct EvalArgs {
  std::string gt, est;
  double max_diff = 0.02;
  double offset = 0.0;
  std::string association = "tum";
  std::string out_dir;    // metrics.json, CSVs, aligned.txt and plots unless overridden
  std::string json_path;  // --json
  std::string ate_csv, rpe_csv, aligned_path;
  std::string plot_dir;  // --plot: plots must be drawn (failing exits 1)
  bool no_plot = false;
  bool pdf = false;
  std::string planes = "xy";
  std::string title, system_name;
  bool quiet = false;
  // ATE
  std::string align = "se3";
  size_t align_first = 0;
  // RPE
  eval::RpeOptions rpe;
  std::string unit = "s", convention = "tum";
};

// Throws InputError for unreadable input and ExitCode{1} when requested plots fail.
void run_eval(EvalArgs& args, bool do_ate, bool do_rpe);

}  // namespace slamkit::cli
