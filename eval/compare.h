#pragma once
// Comparing several evaluated runs (folders holding metrics.json and errors.csv): a table in
// Markdown and CSV (the paper's tables are results_table.h's); the box plot is drawn by
// plot_compare.py (through plot.py).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace slamkit::eval {

struct EvaluatedRun {
  std::filesystem::path dir;
  std::string name;      // settings.system_name, else the folder name; unique in a list
  std::string sequence;  // settings.title, or "" when absent
  nlohmann::json metrics;
};

// Reads RUN/metrics.json of each folder (InputError naming the file if missing, malformed,
// without an "ate" section, or holding a table value that is not a finite number).
std::vector<EvaluatedRun> load_runs(const std::vector<std::filesystem::path>& dirs);

// The value at `path` ("ate.rmse", "rpe.trans.rmse") of the run's metrics.json, or null when
// absent. load_runs has checked that the values of the comparison table are finite numbers.
const nlohmann::json* metric_value(const EvaluatedRun& run, const std::string& path);

// One row per run: ATE pairs and statistics, RPE pairs and RMSEs (blank without RPE).
void write_comparison_markdown(const std::filesystem::path& path,
                               const std::vector<EvaluatedRun>& runs);
void write_comparison_csv(const std::filesystem::path& path, const std::vector<EvaluatedRun>& runs);

}  // namespace slamkit::eval
