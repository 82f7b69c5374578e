#pragma once
// The evaluation run behind `slamkit eval ate|rpe|all`, also used by `slamkit run` and `track`
// when the sequence has groundtruth: read both files, associate, compute, write, summarise, plot.
#include <optional>
#include <string>
#include <vector>

#include "eval/metrics/rpe.h"

namespace slamkit::eval {

// Options of `eval ate`, `eval rpe` and `eval all` (each registers the ones it uses).
struct EvaluationRequest {
  std::string gt, est;
  // tum (the benchmark scripts) or evo: the defaults of the rules left unset below
  // (association, max_diff, duplicate stamps, RPE convention). See eval/README.md.
  std::string convention = "tum";
  std::optional<double> max_diff;  // unset: 0.02 s (tum) or 0.01 s (evo)
  double offset = 0.0;
  std::string association;  // tum or evo; "" = the convention's
  std::string duplicates;   // last or first; "" = the convention's
  std::string time_unit = "s";
  // tum, kitti or euroc; "" = detected from the content. --gt-format / --est-format win over
  // --format.
  std::string format, gt_format, est_format;
  std::string kitti_times;  // --times: the KITTI times.txt of KITTI inputs ("" = pose index)
  std::string out_dir;    // metrics.json, CSVs, aligned.txt and plots unless overridden
  std::string json_path;  // --json
  std::string ate_csv, rpe_csv, aligned_path;
  std::string plot_dir;  // --plot: plots must be drawn (failing exits 1)
  bool no_plot = false;
  bool pdf = false;
  std::string planes = "xy";
  std::string title, system_name;
  bool quiet = false;
  // ATE (and RPE's scale: a sim3 alignment scales the estimate before RPE, as evo_rpe -as)
  std::string align = "se3";
  size_t align_first = 0;
  // RPE
  RpeOptions rpe;
  std::string unit = "s";
  std::string rpe_convention;  // tum or evo; "" = the convention's
};

// "xy,xz" -> {"xy", "xz"}: the trajectory plot planes of --planes.
std::vector<std::string> split_planes(const std::string& text);

// Throws InputError for unreadable input. Returns false (after saying why on stderr) when plots
// asked for with --plot were not drawn.
bool run_evaluation(EvaluationRequest& request, bool do_ate, bool do_rpe);

// `eval kitti`: the KITTI odometry metric over the associated frames (for KITTI files without
// times.txt, frame by frame), into metrics.json ("kitti") and the summary. InputError when the
// groundtruth path is too short for a 100 m segment.
void run_kitti_evaluation(EvaluationRequest& request);

}  // namespace slamkit::eval
