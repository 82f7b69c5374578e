#pragma once
// `slamkit regress`: load a suite, run its entries, compare with the baselines, write the
// reports, optionally store new baselines. bin/cmd_regress.cpp only fills the options.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamkit::regress {

struct RegressOptions {
  std::filesystem::path suite_file;
  std::filesystem::path out;
  std::optional<std::filesystem::path> data_dir;  // relative folders, TUM downloads
  std::filesystem::path baselines_dir;            // empty: <suite folder>/baselines/<suite name>
  std::filesystem::path history_file;             // this run's; empty: <out>/history.csv
  int jobs = 1;
  int threads = 0;  // per run; 0: the cores shared out among the jobs
  bool force = false;
  bool update_baselines = false;
  // Also append to <suite folder>/history.csv, the tracked history (as update_baselines does):
  // otherwise a checkout stays clean after a run.
  bool record = false;
  bool download = true;
  std::filesystem::path slamkit;          // the executable that runs the entries
  std::filesystem::path download_script;  // datasets/download_tum.sh
  std::vector<std::string> presets;       // synthetic preset names
};

// The exit code: 0 when every entry ran and is within tolerance (or baselines were updated),
// 1 on a regression or a failed run. Bad input (the suite, a baseline file) is an InputError.
int run_regression(const RegressOptions& options);

// datasets/download_tum.sh in the source tree, or $SLAMKIT_DOWNLOAD_SCRIPT.
std::filesystem::path default_download_script();
// The TUM sequence names the download script knows (its --list).
std::vector<std::string> tum_names(const std::filesystem::path& script);

}  // namespace slamkit::regress
