// slamkit eval ate|rpe|all|compare: judge any TUM-format trajectory against groundtruth, as the
// TUM benchmark scripts (evaluate_ate.py, evaluate_rpe.py) and evo do. The metrics live in
// eval/ (plain functions on trajectories); this file only wires files, options and output.
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

struct CompareArgs {
  std::vector<std::string> runs;
  std::string out_dir;
  bool pdf = false;
  std::string title;
  bool quiet = false;
};

void add_common_options(CLI::App* cmd, EvalArgs& a) {
  cmd->add_option("groundtruth", a.gt, "Groundtruth trajectory (TUM format)")->required();
  cmd->add_option("estimate", a.est, "Estimated trajectory (TUM format)")->required();
  cmd->add_option("--max-diff", a.max_diff, "Association tolerance in seconds")
      ->capture_default_str();
  cmd->add_option("--offset", a.offset, "Time offset added to estimate stamps (s)")
      ->capture_default_str();
  cmd->add_option("--association", a.association,
                  "tum: greedy one-to-one (associate.py); evo: nearest per estimate pose")
      ->capture_default_str();
  cmd->add_option("--out", a.out_dir,
                  "Folder for metrics.json, the error CSVs, aligned.txt and plots");
  cmd->add_option("--json", a.json_path, "metrics.json path (merged into if it exists)");
  cmd->add_option("--plot", a.plot_dir, "Draw plots into this folder (error if impossible)");
  cmd->add_flag("--no-plot", a.no_plot, "Do not draw plots into --out");
  cmd->add_flag("--pdf", a.pdf, "Also write PDF plots");
  cmd->add_option("--title", a.title, "Sequence name for titles (default: groundtruth folder)");
  cmd->add_option("--system-name", a.system_name,
                  "System name for titles (default: estimate file name)");
  cmd->add_flag("--quiet", a.quiet, "Print nothing (errors still go to stderr)");
}

void add_ate_options(CLI::App* cmd, EvalArgs& a) {
  cmd->add_option("--align", a.align, "se3 (Horn/Umeyama), sim3, translation or none")
      ->capture_default_str();
  cmd->add_option("--align-first", a.align_first,
                  "Align on the first N pairs only (1 = first poses; 0 = all)")
      ->capture_default_str();
  cmd->add_option("--aligned", a.aligned_path, "Write the aligned estimate (TUM format)");
  cmd->add_option("--planes", a.planes, "Trajectory plot planes, e.g. xy,xz,yz")
      ->capture_default_str();
}

void add_rpe_options(CLI::App* cmd, EvalArgs& a) {
  cmd->add_option("--delta", a.rpe.delta, "Pair distance, in --unit")->capture_default_str();
  cmd->add_option("--unit", a.unit, "s (seconds), f (frames), m (metres), deg")
      ->capture_default_str();
  cmd->add_flag("--all-pairs", a.rpe.all_pairs,
                "tum: every pose pair (delta ignored); evo: a pair at every pose");
  cmd->add_option("--rpe-convention", a.convention,
                  "tum (evaluate_rpe.py) or evo (see eval/README.md)")
      ->capture_default_str();
}

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

void run_compare(const CompareArgs& args) {
  std::vector<fs::path> dirs(args.runs.begin(), args.runs.end());
  const std::vector<eval::EvaluatedRun> runs = eval::load_runs(dirs);
  const fs::path out(args.out_dir);
  eval::write_comparison_markdown(out / "comparison.md", runs);
  eval::write_comparison_csv(out / "comparison.csv", runs);
  if (!args.quiet) {
    std::ifstream table(out / "comparison.md");
    std::cout << table.rdbuf();
  }
  const eval::PlotPython python = eval::find_plot_python();
  if (!python.interpreter) {
    std::cerr << "slamkit: note: no comparison plot drawn: " << python.problem
              << "; the tables were written\n";
    return;
  }
  std::vector<std::string> plot_args = {eval::plot_script("plot_compare.py").string(), "--out",
                                        out.string()};
  if (!args.title.empty()) plot_args.insert(plot_args.end(), {"--title", args.title});
  if (args.pdf) plot_args.push_back("--pdf");
  for (const auto& run : runs)
    plot_args.insert(plot_args.end(), {"--run", run.name, run.dir.string()});
  const int code = eval::run_program(*python.interpreter, plot_args);
  if (code != 0) {
    std::cerr << "slamkit: error: the comparison plotting script failed (exit code " << code
              << ")\n";
    throw ExitCode{1};
  }
  if (!args.quiet) std::printf("comparison written to %s\n", out.string().c_str());
}

const bool kRegistered = register_command([](CLI::App& root) {
  CLI::App* eval_cmd =
      root.add_subcommand("eval", "Evaluate a trajectory against groundtruth (ATE, RPE)");
  eval_cmd->require_subcommand(1);

  auto ate = std::make_shared<EvalArgs>();
  CLI::App* ate_cmd = eval_cmd->add_subcommand(
      "ate", "Absolute trajectory error after alignment (the benchmark's evaluate_ate.py)");
  add_common_options(ate_cmd, *ate);
  add_ate_options(ate_cmd, *ate);
  ate_cmd->add_option("--csv", ate->ate_csv, "Per-pose error CSV (errors.csv)");
  ate_cmd->callback([ate] { run_eval(*ate, true, false); });

  auto rpe = std::make_shared<EvalArgs>();
  CLI::App* rpe_cmd = eval_cmd->add_subcommand(
      "rpe", "Relative pose error over a fixed delta (the benchmark's evaluate_rpe.py)");
  add_common_options(rpe_cmd, *rpe);
  add_rpe_options(rpe_cmd, *rpe);
  rpe_cmd->add_option("--csv", rpe->rpe_csv, "Per-pair error CSV (rpe.csv)");
  rpe_cmd->callback([rpe] { run_eval(*rpe, false, true); });

  auto all = std::make_shared<EvalArgs>();
  CLI::App* all_cmd =
      eval_cmd->add_subcommand("all", "ATE and RPE in one run (files read once; CSVs go to --out)");
  add_common_options(all_cmd, *all);
  add_ate_options(all_cmd, *all);
  add_rpe_options(all_cmd, *all);
  all_cmd->callback([all] { run_eval(*all, true, true); });

  auto cmp = std::make_shared<CompareArgs>();
  CLI::App* cmp_cmd = eval_cmd->add_subcommand(
      "compare", "Compare evaluated runs (folders with metrics.json and errors.csv)");
  cmp_cmd->add_option("runs", cmp->runs, "Run folders")->required();
  cmp_cmd->add_option("--out", cmp->out_dir, "Output folder")->required();
  cmp_cmd->add_option("--title", cmp->title, "Plot title (default: the runs' sequence)");
  cmp_cmd->add_flag("--pdf", cmp->pdf, "Also write a PDF plot");
  cmp_cmd->add_flag("--quiet", cmp->quiet, "Print nothing");
  cmp_cmd->callback([cmp] { run_compare(*cmp); });
});

}  // namespace
}  // namespace slamkit::cli
