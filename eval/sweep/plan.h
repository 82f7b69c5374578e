#pragma once
// A sweep's numbered jobs: one per suite entry, variant and seed, in that order. `sweep plan`
// writes them to DIR/jobs.tsv (index, entry, variant, seed, run folder) under a header naming
// the sweep file, its hash and the data folder; every later command (run, task, status,
// collect) reads the plan back from there and refuses it if the sweep file changed since.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "eval/regression/runner.h"
#include "eval/sweep/sweep_file.h"

namespace slamkit::sweep {

struct Job {
  int index = 0;
  std::string entry;    // the suite entry's name
  std::string variant;  // the variant's name
  std::optional<uint64_t> seed;
  std::filesystem::path run_folder;  // relative to the sweep folder

  std::string label() const;  // variant/entry/seed1, for progress lines and reports
};

struct Plan {
  std::filesystem::path dir;  // the sweep folder
  Sweep sweep;
  std::optional<std::filesystem::path> data_dir;
  std::vector<Job> jobs;
  std::vector<regress::SuiteEntry> entries;  // per job: the sequence and settings it runs

  // Where job `index` runs and what it runs, for the regression runner.
  regress::RunRequest request(size_t index) const;
  std::vector<regress::RunRequest> requests() const;
};

// Expands the sweep file and writes DIR/jobs.tsv (and nothing else); returns the plan.
Plan write_plan(const std::filesystem::path& sweep_file, const std::filesystem::path& dir,
                const regress::SuiteContext& context);

// Reads DIR/jobs.tsv and the sweep file it names (with the data folder recorded at planning).
// InputError when the folder holds no plan, or the sweep file or its jobs changed since.
Plan load_plan(const std::filesystem::path& dir, regress::SuiteContext context);

}  // namespace slamkit::sweep
