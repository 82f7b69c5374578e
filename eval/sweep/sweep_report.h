#pragma once
// `slamkit sweep collect`'s files, in the regression report's format and style: report.md and a
// self-contained report.html (the best variant per metric with its margin, ATE over variants x
// sequences as a table and a heatmap, the missing or failed tasks with their Slurm state and
// log, every run's metrics), runs.csv (one line per job, every tracked metric at full
// precision), ate_table.csv and ate_heatmap.png.
#include <filesystem>

#include "eval/sweep/results.h"

namespace slamkit::sweep {

struct SweepReportFiles {
  std::filesystem::path markdown, html, runs_csv, ate_table, heatmap;  // heatmap empty: not drawn
};

SweepReportFiles write_sweep_report(const SweepResults& results);

}  // namespace slamkit::sweep
