#pragma once
// The evaluation run behind `slamkit eval ate|rpe|all`, also used by `slamkit run` and `track`
// when the sequence has groundtruth: read both files, associate, compute, write, summarise, plot.
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/metrics/ate.h"
#include "eval/metrics/rpe.h"
#include "eval/plotting.h"
#include "io/trajectory_io.h"

namespace slamkit::eval {

// Options of `eval ate`, `eval rpe` and `eval all` (each registers the ones it uses).
struct EvaluationRequest {
  std::string gt, est;
  // In-process callers (the Python module) may give trajectories already in memory: gt and est
  // then only name them in messages, and metrics.json's inputs have no path or checksum.
  std::shared_ptr<const TrajectoryFile> gt_data, est_data;
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
  FigureFiles figures;
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

// What an evaluation computed, for in-process callers: the trajectories as read, the
// metrics.json it wrote (or would have written into an empty file) and the per-pose and per-pair
// results.
struct EvaluationResult {
  std::shared_ptr<const TrajectoryFile> gt, est;
  nlohmann::json metrics = nlohmann::json::object();
  std::optional<AteResult> ate;
  std::optional<RpeResult> rpe;
};

// Throws InputError for unreadable input. Returns false (after saying why on stderr) when plots
// asked for with --plot were not drawn. Fills `result` when given.
bool run_evaluation(EvaluationRequest& request, bool do_ate, bool do_rpe,
                    EvaluationResult* result = nullptr);

// The (groundtruth, estimate) index pairs the evaluation would measure: the inputs read (or
// given) and associated under the request's rules, with the same checks.
std::vector<IndexPair> associate_inputs(EvaluationRequest& request);

// `eval kitti`: the KITTI odometry metric over the associated frames (for KITTI files without
// times.txt, frame by frame), into metrics.json ("kitti") and the summary. InputError when the
// groundtruth path is too short for a 100 m segment.
void run_kitti_evaluation(EvaluationRequest& request);

}  // namespace slamkit::eval
