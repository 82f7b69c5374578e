#pragma once
// A suite's results as data, and the files written from them: report.md and a self-contained
// report.html for people, junit.xml for CI dashboards, a line per entry in history.csv.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "eval/regression/baseline.h"
#include "eval/regression/comparison.h"
#include "eval/regression/runner.h"
#include "eval/regression/suite.h"

namespace slamkit::regress {

struct EntryResult {
  const SuiteEntry* entry = nullptr;
  EntryRun run;  // run.ok false: run.error says why, no metrics
  RunMetrics metrics;
  std::string settings_hash;         // of the run's settings.yaml
  std::optional<Baseline> baseline;  // as it was before this run
  bool baseline_same_machine = false;  // its timing is judged only then
  std::vector<MetricComparison> comparisons;

  bool failed() const;  // the run failed or a metric regressed or went missing
  bool has_warning() const;
};

struct SuiteReport {
  const Suite* suite = nullptr;
  Provenance current;  // this run's version, machine and date (settings hash per entry)
  std::vector<EntryResult> entries;
  std::filesystem::path out;              // the report folder
  std::filesystem::path comparison_plot;  // empty when not drawn
  std::filesystem::path history_plot;
  bool baselines_updated = false;

  int failures() const;
};

void write_report_markdown(const std::filesystem::path& file, const SuiteReport& report);
// Plots embedded as base64 PNG: the file is viewed without the run folders or a network.
void write_report_html(const std::filesystem::path& file, const SuiteReport& report);
// One <testcase> per entry and metric (plus one for the run itself), <failure> on a regression.
void write_junit(const std::filesystem::path& file, const SuiteReport& report);

// Appends a line per entry (date, suite, entry, version, settings hash, the run's finish time,
// every tracked metric) unless a line for that run is already there: a resumed suite does not
// count its reused runs twice.
void append_history(const std::filesystem::path& file, const SuiteReport& report);

// The suite's plots, drawn by eval's plot.py in one process: the box plot across entries
// (ate_comparison.png) and ATE over versions (ate_history.png) from the history files read in
// order. Sets report.comparison_plot and report.history_plot to the PNGs drawn; a note on
// stderr says why when none were.
void draw_suite_plots(const std::vector<std::filesystem::path>& histories, SuiteReport& report);

}  // namespace slamkit::regress
