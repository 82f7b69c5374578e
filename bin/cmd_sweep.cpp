// slamkit sweep plan|run|task|status|collect: a regression suite times a settings grid times
// seeds, run on this machine or as a Slurm job array, merged into one report. The work is in
// eval/sweep/; this file only wires the options.
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include "bin/command.h"
#include "bin/output_folder.h"
#include "core/error.h"
#include "datasets/synth/trajectory_presets.h"
#include "eval/regression/regression.h"
#include "eval/sweep/commands.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  fs::path sweep_file, dir;
  std::string data, backend = "local";
  int jobs = 1, threads = 0, index = 0;
  bool resubmit_missing = false;
  bool allow_incomplete = false;
  sweep::SlurmOptions slurm;
};

sweep::SweepEnvironment environment(const SweepArgs& args) {
  sweep::SweepEnvironment env;
  const char* data = std::getenv("SLAMKIT_DATA");
  if (!args.data.empty())
    env.suite.data_dir = args.data;
  else if (data && *data)
    env.suite.data_dir = data;
  env.suite.presets = synth::preset_names();
  env.download_script = regress::default_download_script();
  env.suite.tum_names = [script = env.download_script] { return regress::tum_names(script); };
  env.slamkit = fs::read_symlink("/proc/self/exe");
  return env;
}

// A failure of the machinery (sbatch refused, a file system error) exits with 1; bad input
// stays an InputError (exit 2).
void finish(const std::function<int()>& command) {
  int code = 0;
  try {
    code = command();
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "slamkit: error: %s\n", e.what());
    code = 1;
  }
  if (code != 0) throw ExitCode{code};
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = root.add_subcommand(
      "sweep",
      "A suite times a settings grid times seeds: plan the jobs, run them here or as a Slurm "
      "job array, follow them, merge them into one report");
  cmd->require_subcommand(1);

  CLI::App* plan = cmd->add_subcommand("plan", "Expand a sweep file into DIR/jobs.tsv");
  plan->add_option("sweep", args->sweep_file, "Sweep file (YAML)")->required();
  plan->add_option("--out", args->dir, "Sweep folder")->required();
  plan->add_option("--data", args->data,
                   "Data folder for relative sequence folders and TUM downloads "
                   "(default: $SLAMKIT_DATA); recorded in the plan");
  plan->callback([args] {
    check_output_folder("--out", args->dir);
    finish([&] { return sweep::plan_sweep(args->sweep_file, args->dir, environment(*args)); });
  });

  CLI::App* run = cmd->add_subcommand(
      "run", "Run the planned jobs that are not finished: here, or as a Slurm job array");
  run->add_option("dir", args->dir, "Sweep folder (from `sweep plan`)")->required();
  run->add_option("--backend", args->backend, "local or slurm")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  run->add_option("--jobs", args->jobs, "local: runs at the same time")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  run->add_option("--threads", args->threads,
                  "local: threads per run (0: the cores shared among the jobs)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  run->add_option("--time", args->slurm.time, "slurm: time limit per task")->capture_default_str();
  run->add_option("--mem", args->slurm.memory, "slurm: memory per task")->capture_default_str();
  run->add_option("--cpus", args->slurm.cpus, "slurm: CPUs per task (the run's threads)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  run->add_option("--max-running", args->slurm.max_running,
                  "slurm: array tasks running at once (the %M of --array; 0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  run->add_option("--partition", args->slurm.partition,
                  "slurm: partition (default: the cluster's)");
  run->add_flag("--resubmit-missing", args->resubmit_missing,
                "slurm: submit again only the tasks that did not finish (failed, cancelled, "
                "timed out, lost with their node, never run)");
  run->callback([args] {
    const sweep::SweepEnvironment env = environment(*args);
    finish([&] {
      if (args->backend == "slurm")
        return sweep::run_slurm(args->dir, args->slurm, args->resubmit_missing, env);
      if (args->resubmit_missing)
        throw_input_error(args->dir.string(), "--resubmit-missing goes with --backend slurm");
      return sweep::run_local(args->dir, args->jobs, args->threads, env);
    });
  });

  CLI::App* task = cmd->add_subcommand("task", "Run one job of the plan (what an array task runs)");
  task->add_option("dir", args->dir, "Sweep folder")->required();
  task->add_option("index", args->index, "Job index (jobs.tsv)")->required();
  task->add_option("--threads", args->threads, "Threads of the run (0: all cores)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  task->callback([args] {
    finish(
        [&] { return sweep::run_task(args->dir, args->index, args->threads, environment(*args)); });
  });

  CLI::App* status = cmd->add_subcommand(
      "status", "Jobs done, pending, running, requeued, failed and missing (run folders, squeue, sacct)");
  status->add_option("dir", args->dir, "Sweep folder")->required();
  status->callback(
      [args] { finish([&] { return sweep::print_status(args->dir, environment(*args)); }); });

  CLI::App* collect = cmd->add_subcommand(
      "collect",
      "Merge the runs into report.md, report.html, runs.csv and the ATE heatmap; while jobs "
      "are not done it names them and exits 1 (merging only with --allow-incomplete)");
  collect->add_option("dir", args->dir, "Sweep folder")->required();
  collect->add_flag("--allow-incomplete", args->allow_incomplete,
                    "Merge the finished runs although some jobs are not done (exit code 1 still "
                    "says so)");
  collect->callback([args] {
    finish([&] {
      return sweep::collect_sweep(args->dir, args->allow_incomplete, environment(*args));
    });
  });
});

}  // namespace
}  // namespace slamkit::cli
