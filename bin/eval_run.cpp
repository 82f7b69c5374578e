#include "bin/eval_run.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "bin/command.h"
#include "eval/association.h"
#include "eval/ate.h"
#include "eval/compare.h"
#include "eval/coverage.h"
#include "eval/error_csv.h"
#include "eval/metrics_json.h"
#include "eval/plotting.h"
#include "eval/rpe.h"
#include "eval/summary.h"
#include "io/trajectory_io.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void warn(const EvalArgs& a, const std::string& text) {
  if (!a.quiet) std::cerr << "slamkit: warning: " << text << "\n";
}

void print_reader_warnings(const EvalArgs& a, const TrajectoryFile& f) {
  const size_t shown = std::min<size_t>(f.warnings.size(), 5);
  for (size_t k = 0; k < shown; ++k) warn(a, f.warnings[k]);
  if (f.warnings.size() > shown)
    warn(a, "... and " + std::to_string(f.warnings.size() - shown) +
                " more (listed in metrics.json inputs)");
}

struct Inputs {
  TrajectoryFile gt, est;
  std::vector<IndexPair> pairs;
  eval::AssociationOptions association;
  eval::Coverage coverage;
};

// Reads both files, associates them and reports coverage; `need_pairs` makes fewer than 2
// associated pairs an error.
Inputs load_inputs(EvalArgs& a, bool need_pairs) {
  Inputs in;
  in.gt = read_tum_trajectory(a.gt);
  in.est = read_tum_trajectory(a.est);
  print_reader_warnings(a, in.gt);
  print_reader_warnings(a, in.est);
  in.association = {eval::parse_association_method(a.association), a.max_diff, a.offset};
  in.pairs = eval::associate(in.gt.trajectory, in.est.trajectory, in.association);
  if (need_pairs)
    eval::require_enough_pairs(in.pairs.size(), in.gt.trajectory, in.est.trajectory, a.gt, a.est,
                               in.association);
  in.coverage = eval::compute_coverage(in.gt.trajectory, in.est.trajectory, in.pairs.size());
  if (const auto text = eval::coverage_warning(in.coverage)) warn(a, *text);
  return in;
}

// Fills in defaults that depend on the file names.
void resolve_outputs(EvalArgs& a) {
  if (a.out_dir.empty()) a.out_dir = a.plot_dir;  // plots are drawn from the data files
  const auto in_out = [&](std::string& path, const char* name) {
    if (path.empty() && !a.out_dir.empty()) path = (fs::path(a.out_dir) / name).string();
  };
  in_out(a.json_path, "metrics.json");
  in_out(a.ate_csv, "errors.csv");
  in_out(a.rpe_csv, "rpe.csv");
  in_out(a.aligned_path, "aligned.txt");
  if (a.title.empty()) {
    const fs::path parent = fs::absolute(a.gt).parent_path();
    a.title =
        parent.filename().empty() ? fs::path(a.gt).stem().string() : parent.filename().string();
  }
  if (a.system_name.empty()) a.system_name = fs::path(a.est).stem().string();
}

json common_json(const EvalArgs& a, const Inputs& in) {
  return {{"settings",
           {{"title", a.title},
            {"system_name", a.system_name},
            {"association", eval::to_string(in.association.method)},
            {"max_diff", a.max_diff},
            {"offset", a.offset}}},
          {"inputs",
           {{"groundtruth", eval::input_json(a.gt, in.gt)},
            {"estimate", eval::input_json(a.est, in.est)}}},
          {"coverage", eval::coverage_json(in.coverage)}};
}

// Runs plot_trajectory_errors.py KIND; returns false (after saying why) when no plot was
// drawn although one was due.
bool draw_plots(const EvalArgs& a, const std::string& kind, const std::string& csv_path) {
  const bool requested = !a.plot_dir.empty();
  if (!requested && (a.no_plot || a.out_dir.empty())) return true;
  if (a.json_path.empty() || csv_path.empty()) return true;
  const std::string dir = requested ? a.plot_dir : a.out_dir;
  const eval::PlotPython python = eval::find_plot_python();
  std::string problem = python.problem;
  if (python.interpreter) {
    std::vector<std::string> args = {eval::plot_script("plot_trajectory_errors.py").string(),
                                     kind,
                                     "--metrics",
                                     a.json_path,
                                     "--csv",
                                     csv_path,
                                     "--out",
                                     dir,
                                     "--title",
                                     a.title,
                                     "--system-name",
                                     a.system_name,
                                     "--planes",
                                     a.planes};
    if (a.pdf) args.push_back("--pdf");
    const int code = eval::run_program(*python.interpreter, args);
    if (code == 0) {
      if (!a.quiet) std::printf("%s plots written to %s\n", kind.c_str(), dir.c_str());
      return true;
    }
    problem = "the plotting script failed (exit code " + std::to_string(code) + ")";
  }
  std::cerr << "slamkit: " << (requested ? "error" : "note") << ": no " << kind
            << " plots drawn: " << problem << "; metrics.json and the CSV were written\n";
  return !requested;
}

// `eval ate`, `eval rpe` and `eval all`: one reading of the inputs, then each metric.
}  // namespace

void run_eval(EvalArgs& a, bool do_ate, bool do_rpe) {
  a.rpe.unit = eval::parse_delta_unit(a.unit);
  a.rpe.convention = eval::parse_rpe_convention(a.convention);
  a.rpe.offset = a.offset;
  const eval::AteOptions ate_options{eval::parse_align_method(a.align), a.align_first};
  // The benchmark's RPE does its own matching; ATE and evo's RPE need associated pairs.
  const bool need_pairs = do_ate || a.rpe.convention == eval::RpeConvention::kEvo;
  const Inputs in = load_inputs(a, need_pairs);
  resolve_outputs(a);
  const Trajectory& gt = in.gt.trajectory;
  const Trajectory& est = in.est.trajectory;

  json update = common_json(a, in);
  std::string summary;
  std::optional<eval::AteResult> ate;
  std::optional<eval::RpeResult> rpe;
  if (do_ate) {
    ate = eval::compute_ate(gt, est, in.pairs, ate_options);
    update["ate"] = eval::ate_json(*ate);
    update["settings"]["align"] = a.align;
    update["settings"]["align_first"] = a.align_first;
    summary += eval::ate_summary(*ate, in.coverage);
  }
  if (do_rpe) {
    rpe = eval::compute_rpe(gt, est, in.pairs, a.rpe, a.est);
    update["rpe"] = eval::rpe_json(*rpe, a.rpe);
    summary += eval::rpe_summary(*rpe, a.rpe);
  }
  if (!a.json_path.empty()) eval::merge_into_metrics_file(a.json_path, update);
  if (ate && !a.ate_csv.empty()) eval::write_ate_csv(a.ate_csv, *ate);
  if (rpe && !a.rpe_csv.empty()) eval::write_rpe_csv(a.rpe_csv, *rpe);
  if (ate && !a.aligned_path.empty())
    write_tum_trajectory(a.aligned_path, eval::apply_alignment(est, ate->alignment),
                         "estimate " + a.est + " aligned to " + a.gt + " (" + a.align + ")");
  if (!a.quiet) std::fputs(summary.c_str(), stdout);
  bool plotted = true;
  if (ate) plotted = draw_plots(a, "ate", a.ate_csv) && plotted;
  if (rpe) plotted = draw_plots(a, "rpe", a.rpe_csv) && plotted;
  if (!plotted) throw ExitCode{1};
}

}  // namespace slamkit::cli
