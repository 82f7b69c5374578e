// slamkit regress SUITE.yaml --out DIR: the whole pipeline over every entry of a suite,
// compared with the stored baselines; exit 0 within tolerance, 1 on a regression, 2 on bad
// input. The work is in eval/regression/; this file only wires the options.
#include <cstdlib>
#include <memory>

#include "bin/command.h"
#include "bin/output_folder.h"
#include "datasets/synth/trajectory_presets.h"
#include "eval/regression/regression.h"

namespace slamkit::cli {
namespace {

struct RegressArgs {
  regress::RegressOptions options;
  std::string data;
};

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<RegressArgs>();
  regress::RegressOptions& o = args->options;
  CLI::App* cmd = root.add_subcommand(
      "regress",
      "Run a regression suite (results/*.yaml) with `slamkit run`, compare with the baselines, "
      "write report.md, report.html and junit.xml; exit 1 on a regression");
  cmd->add_option("suite", o.suite_file, "Suite file (YAML)")->required();
  cmd->add_option("--out", o.out, "Output folder: runs/<entry>/, reports")->required();
  cmd->add_option("--jobs", o.jobs, "Entries run at the same time")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "Threads per run (0: the cores shared among the jobs)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("--update-baselines", o.update_baselines,
                "Store this run's metrics as the baselines, print what changed, and record the "
                "run in <suite folder>/history.csv");
  cmd->add_flag("--record", o.record,
                "Append this run to <suite folder>/history.csv, the tracked history (kept "
                "unchanged otherwise)");
  cmd->add_flag("--force", o.force, "Run every entry again, even when a finished run exists");
  cmd->add_option("--data", args->data,
                  "Data folder for relative sequence folders and TUM downloads "
                  "(default: $SLAMKIT_DATA)");
  cmd->add_flag("!--no-download", o.download, "Never download: a missing TUM sequence is an error");
  cmd->add_option("--baselines", o.baselines_dir,
                  "Baseline folder (default: <suite folder>/baselines/<suite name>)");
  cmd->add_option("--history", o.history_file,
                  "This run's history file, appended to (default: <out>/history.csv)");
  cmd->callback([args] {
    check_output_folder("--out", args->options.out);
    regress::RegressOptions options = args->options;
    const char* env = std::getenv("SLAMKIT_DATA");
    if (!args->data.empty())
      options.data_dir = args->data;
    else if (env && *env)
      options.data_dir = env;
    options.slamkit = std::filesystem::read_symlink("/proc/self/exe");
    options.download_script = regress::default_download_script();
    options.presets = synth::preset_names();
    const int code = regress::run_regression(options);
    if (code != 0) throw ExitCode{code};
  });
});

}  // namespace
}  // namespace slamkit::cli
