#pragma once
// The metrics a regression run tracks, and reading them from a run folder: metrics.json (ATE,
// RPE, the map's quality on synthetic sequences), tracking.csv (frames lost) and timing.json
// (run time, frames/s). Plain functions on files, like the rest of eval.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "eval/regression/suite.h"

namespace slamkit::regress {

struct MetricInfo {
  std::string key;    // as in suites, baselines and history.csv
  std::string label;  // for reports
  std::string unit;   // "m", "deg", "frames", "s", "frames/s", ""
  bool higher_is_better = false;
  bool warn_only = false;  // timing: machines differ, so it never fails a suite
  Tolerance tolerance;     // the default
};

// In report order.
const std::vector<MetricInfo>& tracked_metrics();
const MetricInfo* find_metric(const std::string& key);

using RunMetrics = std::map<std::string, double>;

// The tracked metrics a finished run folder holds (a sequence without groundtruth has no ATE;
// only synthetic ones have map quality). InputError naming the file when one is malformed.
RunMetrics read_run_metrics(const std::filesystem::path& run_dir);

}  // namespace slamkit::regress
