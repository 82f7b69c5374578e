#include "eval/evaluation_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "eval/metrics/association.h"
#include "eval/metrics/ate.h"
#include "eval/compare.h"
#include "eval/metrics/coverage.h"
#include "eval/metrics/error_csv.h"
#include "eval/metrics/kitti_odometry.h"
#include "eval/metrics/metrics_json.h"
#include "eval/plotting.h"
#include "eval/metrics/rpe.h"
#include "eval/metrics/summary.h"
#include "io/trajectory_format.h"
#include "io/trajectory_io.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void warn(const EvaluationRequest& a, const std::string& text) {
  if (!a.quiet) std::cerr << "slamkit: warning: " << text << "\n";
}

void print_reader_warnings(const EvaluationRequest& a, const TrajectoryFile& f) {
  const size_t shown = std::min<size_t>(f.warnings.size(), 5);
  for (size_t k = 0; k < shown; ++k) warn(a, f.warnings[k]);
  if (f.warnings.size() > shown)
    warn(a, "... and " + std::to_string(f.warnings.size() - shown) +
                " more (listed in metrics.json inputs)");
}

// The rules in force: each one given explicitly, else the convention's.
struct Rules {
  AssociationOptions association;
  TrajectoryReadOptions reading;
};

Rules resolve_rules(EvaluationRequest& a) {
  const bool evo = parse_association_method(a.convention) == AssociationMethod::kEvo;
  const auto pick = [&](const std::string& given, const char* tum, const char* evo_rule) {
    return given.empty() ? std::string(evo ? evo_rule : tum) : given;
  };
  Rules r;
  r.association.method = parse_association_method(pick(a.association, "tum", "evo"));
  r.association.max_diff = a.max_diff.value_or(evo ? kEvoMaxDiff : kTumMaxDiff);
  r.association.offset = a.offset;
  r.reading.duplicates = parse_duplicate_stamps(pick(a.duplicates, "last", "all"));
  r.reading.time_unit = parse_time_unit(a.time_unit);
  a.rpe.convention = parse_rpe_convention(pick(a.rpe_convention, "tum", "evo"));
  return r;
}

// Stamps beyond 1e11 s (the year 5138) are not seconds; pairing them as seconds gives
// nonsense (every pose paired with itself), so say what they look like.
void require_plausible_stamps(const Trajectory& t, const std::string& name) {
  const double largest = std::max(std::abs(t.start_time()), std::abs(t.end_time()));
  if (largest <= 1e11) return;
  char text[320];
  std::snprintf(text, sizeof text, "timestamps reach %.17g, beyond 1e11 s (the year 5138): %s",
                largest,
                largest >= 1e17   ? "looks like nanoseconds; pass --time-unit ns"
                : largest >= 1e14 ? "looks like microseconds; pass --time-unit us"
                                  : "not a time in seconds (--time-unit converts ns or us)");
  throw_input_error(name, text);
}

// A file's format: its own option, else --format, else detected (nullopt).
std::optional<TrajectoryFormat> file_format(const std::string& own, const std::string& both) {
  const std::string& given = own.empty() ? both : own;
  if (given.empty()) return std::nullopt;
  return parse_trajectory_format(given);
}

std::optional<fs::path> kitti_times(const EvaluationRequest& a) {
  if (a.kitti_times.empty()) return std::nullopt;
  return fs::path(a.kitti_times);
}

struct Inputs {
  std::shared_ptr<const TrajectoryFile> gt, est;
  std::vector<IndexPair> pairs;
  AssociationOptions association;
  TrajectoryReadOptions reading;
  Coverage coverage;
};

// Reads both files, associates them and reports coverage; `need_pairs` makes fewer than 2
// associated pairs an error, as is no overlap in time at all.
Inputs load_inputs(EvaluationRequest& a, const Rules& rules, bool need_pairs) {
  Inputs in;
  in.association = rules.association;
  in.reading = rules.reading;
  // In-process callers may give a trajectory already read; else it is read in its format.
  const auto read = [&](const std::shared_ptr<const TrajectoryFile>& given,
                        const std::string& path, const std::string& format) {
    return given ? given
                 : std::make_shared<const TrajectoryFile>(read_trajectory(
                       path, file_format(format, a.format), in.reading, kitti_times(a)));
  };
  in.gt = read(a.gt_data, a.gt, a.gt_format);
  in.est = read(a.est_data, a.est, a.est_format);
  const Trajectory& gt = in.gt->trajectory;
  const Trajectory& est = in.est->trajectory;
  require_plausible_stamps(gt, a.gt);
  require_plausible_stamps(est, a.est);
  print_reader_warnings(a, *in.gt);
  print_reader_warnings(a, *in.est);
  require_associable(gt, est, a.gt, a.est, in.association);
  in.pairs = associate(gt, est, in.association);
  in.coverage = compute_coverage(gt, est, in.pairs.size());
  // Without any overlap in time no metric can be computed: said as for ATE, not as RPE's
  // "no pose pair" after a coverage warning.
  if (need_pairs || (in.pairs.empty() && in.coverage.overlap_s == 0))
    require_enough_pairs(in.pairs.size(), gt, est, a.gt, a.est, in.association);
  if (const auto text = coverage_warning(in.coverage)) warn(a, *text);
  return in;
}

// Statistics that overflowed are refused rather than written (as null) or printed (as inf).
void require_finite(const ErrorStats& s, const std::string& what, const std::string& file) {
  for (double v : {s.rmse, s.mean, s.median, s.std, s.min, s.max})
    if (!std::isfinite(v))
      throw_input_error(file, what +
                                  " statistics are not finite: the input's values overflow "
                                  "the arithmetic; check this file for absurd values");
}

// A time delta shorter than the poses' spacing pairs each pose with itself or a neighbour.
void warn_short_time_delta(const EvaluationRequest& a, const Trajectory& est) {
  if (a.rpe.unit != DeltaUnit::kSeconds || a.rpe.all_pairs || est.size() < 2) return;
  std::vector<double> intervals(est.size() - 1);
  for (size_t k = 1; k < est.size(); ++k) intervals[k - 1] = est.stamp(k) - est.stamp(k - 1);
  const double median = compute_stats(intervals).median;
  if (!(a.rpe.delta < median)) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "RPE delta %g s is below the median interval between estimated poses (%g s): "
                "most poses are paired with themselves or a neighbour",
                a.rpe.delta, median);
  warn(a, text);
}

// Fills in defaults that depend on the file names.
void resolve_outputs(EvaluationRequest& a) {
  if (a.out_dir.empty()) a.out_dir = a.plot_dir;  // plots are drawn from the data files
  const auto in_out = [&](std::string& path, const char* name) {
    if (path.empty() && !a.out_dir.empty()) path = (fs::path(a.out_dir) / name).string();
  };
  in_out(a.json_path, "metrics.json");
  in_out(a.ate_csv, "errors.csv");
  in_out(a.rpe_csv, "rpe.csv");
  in_out(a.aligned_path, "aligned.txt");
  if (a.title.empty() && a.gt_data) a.title = a.gt;
  if (a.title.empty()) {
    const fs::path parent = fs::absolute(a.gt).parent_path();
    a.title =
        parent.filename().empty() ? fs::path(a.gt).stem().string() : parent.filename().string();
  }
  if (a.system_name.empty()) a.system_name = fs::path(a.est).stem().string();
}

// input_json with the times.txt that stamped a KITTI file.
json input_json_of(const EvaluationRequest& a, const std::string& path, const TrajectoryFile& f) {
  json j = input_json(path, f);
  if (f.format == "kitti") j["times"] = a.kitti_times.empty() ? "pose index" : a.kitti_times;
  return j;
}

json common_json(const EvaluationRequest& a, const Inputs& in) {
  return {{"settings",
           {{"title", a.title},
            {"system_name", a.system_name},
            {"convention", a.convention},
            {"association", to_string(in.association.method)},
            {"max_diff", in.association.max_diff},
            {"offset", a.offset},
            {"time_unit", to_string(in.reading.time_unit)},
            {"duplicate_stamps", to_string(in.reading.duplicates)}}},
          {"inputs",
           {{"groundtruth", input_json_of(a, a.gt_data ? "" : a.gt, *in.gt)},
            {"estimate", input_json_of(a, a.est_data ? "" : a.est, *in.est)}}},
          {"coverage", coverage_json(in.coverage)}};
}

}  // namespace

std::vector<std::string> split_planes(const std::string& text) {
  std::vector<std::string> planes;
  std::stringstream list(text);
  for (std::string plane; std::getline(list, plane, ',');) planes.push_back(plane);
  return planes;
}

namespace {

// Adds the figures of `kind` (ate or rpe), drawn from the files just written, when plots are
// due: asked for with --plot, or into --out unless --no-plot.
void add_figures(const EvaluationRequest& a, const std::string& kind, const std::string& csv_path,
                 json& figures) {
  const bool requested = !a.plot_dir.empty();
  if (!requested && (a.no_plot || a.out_dir.empty())) return;
  if (a.json_path.empty() || csv_path.empty()) return;
  json figure = {{"figure", kind},   {"metrics", a.json_path},
                 {"csv", csv_path},  {"out", requested ? a.plot_dir : a.out_dir},
                 {"title", a.title}, {"system_name", a.system_name}};
  figure.update(figure_files(a.figures));
  if (kind == "ate") figure["planes"] = split_planes(a.planes);
  figures.push_back(figure);
}

// Draws every figure in one process; returns false (after saying why) when plots asked for
// with --plot were not drawn.
bool draw_plots(const EvaluationRequest& a, const json& figures) {
  if (figures.empty()) return true;
  std::string what = figures[0]["figure"];  // "ate", "rpe" or "ate and rpe"
  if (figures.size() == 2) what += " and " + figures[1]["figure"].get<std::string>();
  const std::string dir = figures[0]["out"];
  const PlotOutcome outcome = draw_figures(figures);
  if (outcome.drawn) {
    if (!a.quiet)
      std::printf("%s plots written to %s in %.2f s\n", what.c_str(), dir.c_str(), outcome.seconds);
    return true;
  }
  const bool requested = !a.plot_dir.empty();
  std::cerr << "slamkit: " << (requested ? "error" : "note") << ": no " << what
            << " plots drawn: " << outcome.problem << "; metrics.json and the CSVs were written\n";
  return !requested;
}

// `eval ate`, `eval rpe` and `eval all`: one reading of the inputs, then each metric.
}  // namespace

bool run_evaluation(EvaluationRequest& a, bool do_ate, bool do_rpe, EvaluationResult* result) {
  const Rules rules = resolve_rules(a);
  a.rpe.unit = parse_delta_unit(a.unit);
  a.rpe.offset = a.offset;
  const AteOptions ate_options{parse_align_method(a.align), a.align_first};
  const bool scale_rpe = do_rpe && ate_options.align == AlignMethod::kSim3;
  // The benchmark's RPE does its own matching; ATE, evo's RPE and a Sim(3) scale need pairs.
  const bool need_pairs = do_ate || scale_rpe || a.rpe.convention == RpeConvention::kEvo;
  const Inputs in = load_inputs(a, rules, need_pairs);
  resolve_outputs(a);
  const Trajectory& gt = in.gt->trajectory;
  const Trajectory& est = in.est->trajectory;
  if (result) {
    result->gt = in.gt;
    result->est = in.est;
  }

  // Each metric writes its files as soon as it is done, so that a million-pose run holds one
  // metric's per-pose data at a time.
  const json common = common_json(a, in);
  Alignment alignment;
  json figures = json::array();
  if (do_ate) {
    AteResult ate = compute_ate(gt, est, in.pairs, ate_options, a.gt, a.est);
    require_finite(ate.trans, "ATE", a.est);
    alignment = ate.alignment;
    json update = common;
    update["ate"] = ate_json(ate);
    update["settings"]["align"] = a.align;
    update["settings"]["align_first"] = a.align_first;
    if (!a.json_path.empty()) merge_into_metrics_file(a.json_path, update);
    if (!a.ate_csv.empty()) write_ate_csv(a.ate_csv, ate);
    if (!a.aligned_path.empty())
      write_tum_trajectory(a.aligned_path, apply_alignment(est, ate.alignment),
                           "estimate " + a.est + " aligned to " + a.gt + " (" + a.align + ")");
    if (!a.quiet) std::fputs(ate_summary(ate, in.coverage).c_str(), stdout);
    add_figures(a, "ate", a.ate_csv, figures);
    if (result) {
      merge_metrics(result->metrics, update);
      result->ate = std::move(ate);
    }
  } else if (scale_rpe) {
    alignment = align(gt, est, in.pairs, ate_options.align, a.align_first, a.gt, a.est);
  }
  if (do_rpe) {
    a.rpe.scale = scale_rpe ? alignment.scale : 1.0;
    warn_short_time_delta(a, est);
    RpeResult rpe = compute_rpe(gt, est, in.pairs, a.rpe, a.est);
    require_finite(rpe.trans, "RPE", a.est);
    require_finite(rpe.rot_deg, "RPE rotation", a.est);
    json update = common;
    update["rpe"] = rpe_json(rpe, a.rpe);
    if (!do_ate) update["settings"]["align"] = a.align;
    if (!a.json_path.empty()) merge_into_metrics_file(a.json_path, update);
    if (!a.rpe_csv.empty()) write_rpe_csv(a.rpe_csv, rpe);
    if (!a.quiet) std::fputs(rpe_summary(rpe, a.rpe).c_str(), stdout);
    add_figures(a, "rpe", a.rpe_csv, figures);
    if (result) {
      merge_metrics(result->metrics, update);
      result->rpe = std::move(rpe);
    }
  }
  return draw_plots(a, figures);
}

std::vector<IndexPair> associate_inputs(EvaluationRequest& a) {
  return load_inputs(a, resolve_rules(a), false).pairs;
}

void run_kitti_evaluation(EvaluationRequest& a) {
  const Inputs in = load_inputs(a, resolve_rules(a), true);
  resolve_outputs(a);
  // The devkit pairs frames by index; here the associated pairs, in order, are the frames.
  std::vector<Eigen::Isometry3d> gt, est;
  for (const IndexPair& pair : in.pairs) {
    gt.push_back(in.gt->trajectory.pose(pair.first));
    est.push_back(in.est->trajectory.pose(pair.second));
  }
  const KittiOdometryResult kitti = compute_kitti_odometry(gt, est);
  if (kitti.segments.empty()) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "groundtruth path over the %zu matched frames is %.3f m: the KITTI metric's "
                  "shortest segment needs more than 100 m",
                  gt.size(), kitti.path_m);
    throw_input_error(a.gt, text);
  }
  json update = common_json(a, in);
  update["kitti"] = kitti_json(kitti, in.pairs.size());
  if (!a.json_path.empty()) merge_into_metrics_file(a.json_path, update);
  if (!a.quiet) std::fputs(kitti_summary(kitti, in.pairs.size()).c_str(), stdout);
}

}  // namespace slamkit::eval
