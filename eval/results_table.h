#pragma once
// The statistics table of compared runs for a paper, as evo_res --save_table writes it: one row
// per run with ATE RMSE/mean/median/std/min/max, RPE translational and rotational RMSE and the
// pair counts, as CSV (every digit, for further tools), Markdown and LaTeX (rounded, the best
// value of each error column in bold). `slamkit eval compare` writes them as table.csv,
// table.md and table.tex.
#include <filesystem>
#include <string>
#include <vector>

#include "eval/compare.h"

namespace slamkit::eval {

// Numbers as metrics.json holds them (the shortest text that reads back to the same double);
// blank where a run has no RPE. Names are quoted where CSV needs it.
std::string results_table_csv(const std::vector<EvaluatedRun>& runs);

// Values in metres share one number of decimals, as do those in degrees: three significant
// digits of the smallest RMSE in that unit, so that the columns line up and the best run's
// digits are all shown. The lowest value of each error column is bold (every one that ties
// after rounding; none in a column with fewer than two values). A missing value is a dash.
std::string results_table_markdown(const std::vector<EvaluatedRun>& runs);
// The same as a booktabs tabular (\usepackage{booktabs}) to \input into a table environment.
std::string results_table_latex(const std::vector<EvaluatedRun>& runs);

// Writes table.csv, table.md and table.tex into `dir` (which exists).
void write_results_tables(const std::filesystem::path& dir, const std::vector<EvaluatedRun>& runs);

}  // namespace slamkit::eval
