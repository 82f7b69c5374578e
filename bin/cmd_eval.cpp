// slamkit eval ate|rpe|all|compare: judge any TUM, KITTI or EuRoC trajectory against groundtruth, as the
// TUM benchmark scripts (evaluate_ate.py, evaluate_rpe.py) and evo do. The metrics live in
// eval/ (plain functions on trajectories); this file only wires files, options and output.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "bin/command.h"
#include "bin/figure_options.h"
#include "bin/output_folder.h"
#include "eval/metrics/association.h"
#include "eval/metrics/ate.h"
#include "eval/compare.h"
#include "eval/metrics/coverage.h"
#include "eval/metrics/error_csv.h"
#include "eval/evaluation_run.h"
#include "eval/metrics/metrics_json.h"
#include "eval/plotting.h"
#include "eval/results_table.h"
#include "eval/metrics/rpe.h"
#include "eval/metrics/summary.h"
#include "io/trajectory_io.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A requested plot that was not drawn ends the command with exit code 1.
void evaluate_or_exit(eval::EvaluationRequest& request, bool do_ate, bool do_rpe) {
  if (!request.out_dir.empty()) check_output_folder("--out", request.out_dir);
  if (!request.plot_dir.empty()) check_output_folder("--plot", request.plot_dir);
  if (!eval::run_evaluation(request, do_ate, do_rpe)) throw ExitCode{1};
}

struct CompareArgs {
  std::vector<std::string> runs;
  std::string out_dir;
  eval::FigureFiles figures;
  bool trajectories = false;
  std::string planes = "xy";
  std::string title;
  bool quiet = false;
};

CLI::Validator planes_validator() {
  return CLI::Validator(
      [](std::string& text) {
        for (const std::string& plane : eval::split_planes(text))
          if (plane != "xy" && plane != "xz" && plane != "yz")
            return "unknown plane '" + plane + "' (use xy, xz or yz)";
        return std::string();
      },
      "PLANES");
}

void add_common_options(CLI::App* cmd, eval::EvaluationRequest& a) {
  cmd->add_option("groundtruth", a.gt, "Groundtruth trajectory (tum, kitti or euroc)")
      ->required();
  cmd->add_option("estimate", a.est, "Estimated trajectory (tum, kitti or euroc)")->required();
  const auto formats = CLI::IsMember({"tum", "kitti", "euroc"});
  cmd->add_option("--format", a.format,
                  "Format of both files: tum, kitti or euroc (default: detected per file)")
      ->check(formats);
  cmd->add_option("--gt-format", a.gt_format, "Format of the groundtruth (wins over --format)")
      ->check(formats);
  cmd->add_option("--est-format", a.est_format, "Format of the estimate (wins over --format)")
      ->check(formats);
  cmd->add_option("--times", a.kitti_times,
                  "KITTI times.txt: the stamps of kitti files (default: the pose index in s)");
  cmd->add_option("--convention", a.convention,
                  "tum (the benchmark scripts) or evo: sets association, --max-diff, "
                  "--duplicate-stamps and --rpe-convention unless given")
      ->check(CLI::IsMember({"tum", "evo"}))
      ->capture_default_str();
  cmd->add_option_function<double>(
         "--max-diff", [&a](const double& v) { a.max_diff = v; },
         "Association tolerance in seconds (default 0.02, evo: 0.01)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--offset", a.offset, "Time offset added to estimate stamps (s)")
      ->capture_default_str();
  cmd->add_option("--association", a.association,
                  "tum: greedy one-to-one (associate.py); evo: nearest per pose of the shorter "
                  "trajectory (default: the convention's)")
      ->check(CLI::IsMember({"tum", "evo"}));
  cmd->add_option("--duplicate-stamps", a.duplicates,
                  "Of a repeated timestamp keep the last line (tum), the first, or all (evo)")
      ->check(CLI::IsMember({"last", "first", "all"}));
  cmd->add_option("--time-unit", a.time_unit, "Unit of the files' timestamps: s, us or ns")
      ->check(CLI::IsMember({"s", "us", "ns"}))
      ->capture_default_str();
  cmd->add_option("--out", a.out_dir,
                  "Folder for metrics.json, the error CSVs, aligned.txt and plots");
  cmd->add_option("--json", a.json_path, "metrics.json path (merged into if it exists)");
  cmd->add_option("--plot", a.plot_dir, "Draw plots into this folder (error if impossible)");
  cmd->add_flag("--no-plot", a.no_plot, "Do not draw plots into --out");
  add_figure_options(cmd, a.figures);
  cmd->add_option("--title", a.title, "Sequence name for titles (default: groundtruth folder)");
  cmd->add_option("--system-name", a.system_name,
                  "System name for titles (default: estimate file name)");
  cmd->add_flag("--quiet", a.quiet, "Print nothing (errors still go to stderr)");
}

void add_ate_options(CLI::App* cmd, eval::EvaluationRequest& a) {
  cmd->add_option("--align", a.align,
                  "se3 (Horn/Umeyama), sim3, translation or none; sim3 also scales the "
                  "estimate for RPE")
      ->capture_default_str();
  cmd->add_option("--align-first", a.align_first,
                  "Align on the first N pairs only (1 = first poses; 0 = all)")
      ->capture_default_str();
  cmd->add_option("--aligned", a.aligned_path, "Write the aligned estimate (TUM format)");
  cmd->add_option("--planes", a.planes, "Trajectory plot planes, e.g. xy,xz,yz")
      ->check(planes_validator())
      ->capture_default_str();
}

void add_rpe_options(CLI::App* cmd, eval::EvaluationRequest& a) {
  cmd->add_option("--delta", a.rpe.delta, "Pair distance, in --unit")->capture_default_str();
  cmd->add_option("--unit", a.unit, "s (seconds), f (frames), m (metres), deg, rad")
      ->capture_default_str();
  cmd->add_flag("--all-pairs", a.rpe.all_pairs,
                "tum: every pose pair (delta ignored); evo: a pair at every pose");
  cmd->add_option("--rpe-convention", a.rpe_convention,
                  "tum (evaluate_rpe.py) or evo (default: the convention's)")
      ->check(CLI::IsMember({"tum", "evo"}));
  cmd->add_option("--delta-tol", a.rpe.rel_delta_tol,
                  "evo all-pairs in m or deg: accept pairs within this fraction of delta")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

void run_compare(const CompareArgs& args) {
  check_output_folder("--out", args.out_dir);
  std::vector<fs::path> dirs(args.runs.begin(), args.runs.end());
  const std::vector<eval::EvaluatedRun> runs = eval::load_runs(dirs);
  const fs::path out(args.out_dir);
  eval::write_comparison_markdown(out / "comparison.md", runs);
  eval::write_comparison_csv(out / "comparison.csv", runs);
  eval::write_results_tables(out, runs);
  if (!args.quiet) {
    std::ifstream table(out / "comparison.md");
    std::cout << table.rdbuf();
  }
  json figure = {
      {"figure", "compare"}, {"out", out.string()}, {"title", args.title}, {"runs", json::array()}};
  for (const auto& run : runs) figure["runs"].push_back({run.name, run.dir.string()});
  figure.update(eval::figure_files(args.figures));
  json figures = json::array({figure});
  if (args.trajectories) {
    figure["figure"] = "trajectories";
    figure["planes"] = eval::split_planes(args.planes);
    figures.push_back(figure);
  }
  const eval::PlotOutcome plot = eval::draw_figures(figures);
  if (plot.python_missing) {
    std::cerr << "slamkit: note: no comparison plot drawn: " << plot.problem
              << "; the tables were written\n";
    return;
  }
  if (!plot.drawn) {
    std::cerr << "slamkit: error: comparison plots not all drawn: " << plot.problem
              << "; the tables were written\n";
    throw ExitCode{1};
  }
  if (!args.quiet) std::printf("comparison written to %s\n", out.string().c_str());
}

const bool kRegistered = register_command([](CLI::App& root) {
  CLI::App* eval_cmd =
      root.add_subcommand("eval", "Evaluate a trajectory against groundtruth (ATE, RPE)");
  eval_cmd->require_subcommand(1);

  auto ate = std::make_shared<eval::EvaluationRequest>();
  CLI::App* ate_cmd = eval_cmd->add_subcommand(
      "ate", "Absolute trajectory error after alignment (the benchmark's evaluate_ate.py)");
  add_common_options(ate_cmd, *ate);
  add_ate_options(ate_cmd, *ate);
  ate_cmd->add_option("--csv", ate->ate_csv, "Per-pose error CSV (errors.csv)");
  ate_cmd->callback([ate] { evaluate_or_exit(*ate, true, false); });

  auto rpe = std::make_shared<eval::EvaluationRequest>();
  CLI::App* rpe_cmd = eval_cmd->add_subcommand(
      "rpe", "Relative pose error over a fixed delta (the benchmark's evaluate_rpe.py)");
  add_common_options(rpe_cmd, *rpe);
  add_rpe_options(rpe_cmd, *rpe);
  rpe->align = "none";
  rpe_cmd
      ->add_option("--align", rpe->align,
                   "sim3: scale the estimate by a Sim(3) alignment first (evo_rpe -as); se3, "
                   "translation and none leave relative poses unchanged")
      ->check(CLI::IsMember({"se3", "sim3", "translation", "none"}))
      ->capture_default_str();
  rpe_cmd->add_option("--csv", rpe->rpe_csv, "Per-pair error CSV (rpe.csv)");
  rpe_cmd->callback([rpe] { evaluate_or_exit(*rpe, false, true); });

  auto all = std::make_shared<eval::EvaluationRequest>();
  CLI::App* all_cmd =
      eval_cmd->add_subcommand("all", "ATE and RPE in one run (files read once; CSVs go to --out)");
  add_common_options(all_cmd, *all);
  add_ate_options(all_cmd, *all);
  add_rpe_options(all_cmd, *all);
  all_cmd->callback([all] { evaluate_or_exit(*all, true, true); });

  auto kitti = std::make_shared<eval::EvaluationRequest>();
  CLI::App* kitti_cmd = eval_cmd->add_subcommand(
      "kitti", "KITTI odometry metric: % and deg/m over 100..800 m segments (the devkit's)");
  add_common_options(kitti_cmd, *kitti);
  kitti_cmd->callback([kitti] {
    if (!kitti->out_dir.empty()) check_output_folder("--out", kitti->out_dir);
    eval::run_kitti_evaluation(*kitti);
  });

  auto cmp = std::make_shared<CompareArgs>();
  CLI::App* cmp_cmd = eval_cmd->add_subcommand(
      "compare", "Compare evaluated runs (folders with metrics.json and errors.csv)");
  cmp_cmd->add_option("runs", cmp->runs, "Run folders")->required();
  cmp_cmd->add_option("--out", cmp->out_dir, "Output folder")->required();
  cmp_cmd->add_option("--title", cmp->title, "Plot title (default: the runs' sequence)");
  add_figure_options(cmp_cmd, cmp->figures);
  cmp_cmd->add_flag("--trajectories", cmp->trajectories,
                    "Also draw the runs' aligned estimates and the groundtruth together "
                    "(trajectories_PLANE, trajectories_xyz; the runs must share a groundtruth)");
  cmp_cmd->add_option("--planes", cmp->planes, "Planes of --trajectories, e.g. xy,xz,yz")
      ->check(planes_validator())
      ->capture_default_str();
  cmp_cmd->add_flag("--quiet", cmp->quiet, "Print nothing");
  cmp_cmd->callback([cmp] { run_compare(*cmp); });
});

}  // namespace
}  // namespace slamkit::cli
