#pragma once
// `slamkit sweep plan|run|task|status|collect`: each reads the plan in the sweep folder, does
// its one job, prints what it did and returns the exit code (0 done, 1 a run failed or results
// are missing; bad input is an InputError, exit 2). bin/cmd_sweep.cpp only fills the options.
#include <filesystem>
#include <string>

#include "eval/regression/suite.h"
#include "eval/sweep/slurm.h"

namespace slamkit::sweep {

// What every command needs besides its own options.
struct SweepEnvironment {
  regress::SuiteContext suite;            // data folder (plan only), presets, TUM names
  std::filesystem::path slamkit;          // the executable that runs the jobs
  std::filesystem::path download_script;  // datasets/download_tum.sh
};

int plan_sweep(const std::filesystem::path& sweep_file, const std::filesystem::path& dir,
               const SweepEnvironment& env);
// Every job that is not finished, `jobs` at a time (threads per run: 0 shares the cores).
int run_local(const std::filesystem::path& dir, int jobs, int threads, const SweepEnvironment& env);
// Submits the jobs that are not finished as one job array. A folder submitted before is
// refused unless resubmit_missing, which submits only the tasks that are neither finished nor
// queued or running.
int run_slurm(const std::filesystem::path& dir, const SlurmOptions& options, bool resubmit_missing,
              const SweepEnvironment& env);
// One job, as an array task runs it.
int run_task(const std::filesystem::path& dir, int index, int threads, const SweepEnvironment& env);
int print_status(const std::filesystem::path& dir, const SweepEnvironment& env);
// Merges the finished runs into DIR's report; an incomplete sweep only with allow_incomplete
// (otherwise it names the jobs that are not done and merges nothing).
int collect_sweep(const std::filesystem::path& dir, bool allow_incomplete,
                  const SweepEnvironment& env);

}  // namespace slamkit::sweep
