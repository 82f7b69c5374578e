// The paper tables of `eval compare` (table.csv, table.md, table.tex) for known runs, to the
// character: rounding, bold best values, missing RPE and the escaping of run names.
#include "eval/results_table.h"

#include <gtest/gtest.h>

#include "support/test_data.h"

namespace slamkit::eval {
namespace {

EvaluatedRun run(const std::string& name, const std::string& metrics) {
  EvaluatedRun r;
  r.dir = name;
  r.name = name;
  r.metrics = nlohmann::json::parse(metrics);
  return r;
}

// Special characters of LaTeX and Markdown in the names; the second run has no RPE.
std::vector<EvaluatedRun> two_runs() {
  return {run("orb_slam & co",
              R"({"ate": {"pairs": 2223, "rmse": 0.008144123, "mean": 0.0071, "median": 0.0065,
                          "std": 0.0039, "min": 0.0002, "max": 0.0251},
                  "rpe": {"pairs": 1998, "trans": {"rmse": 0.007161},
                          "rot_deg": {"rmse": 0.4567}}})"),
          run("mine|v2, #1 50%",
              R"({"ate": {"pairs": 2200, "rmse": 0.0123, "mean": 0.0101, "median": 0.0099,
                          "std": 0.007, "min": 0.0001, "max": 0.0402}})")};
}

TEST(ResultsTable, CsvHoldsEveryDigitAndQuotesANameWithAComma) {
  EXPECT_EQ(results_table_csv(two_runs()),
            "run,ate_rmse_m,ate_mean_m,ate_median_m,ate_std_m,ate_min_m,ate_max_m,"
            "rpe_trans_rmse_m,rpe_rot_rmse_deg,ate_pairs,rpe_pairs\n"
            "orb_slam & co,0.008144123,0.0071,0.0065,0.0039,0.0002,0.0251,0.007161,0.4567,2223,"
            "1998\n"
            "\"mine|v2, #1 50%\",0.0123,0.0101,0.0099,0.007,0.0001,0.0402,,,2200,\n");
}

// Metres to 5 decimals (3 digits of the smallest RMSE, 0.00716), degrees to 3 (0.457).
TEST(ResultsTable, MarkdownRoundsPerUnitBoldsTheBestAndEscapesTheBar) {
  EXPECT_EQ(results_table_markdown(two_runs()),
            "| Run | ATE RMSE [m] | ATE mean [m] | ATE median [m] | ATE std [m] | ATE min [m] | "
            "ATE max [m] | RPE trans. RMSE [m] | RPE rot. RMSE [deg] | ATE pairs | RPE pairs |\n"
            "|:---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
            "| orb\\_slam & co | **0.00814** | **0.00710** | **0.00650** | **0.00390** | 0.00020 | "
            "**0.02510** | 0.00716 | 0.457 | 2223 | 1998 |\n"
            "| mine\\|v2, #1 50% | 0.01230 | 0.01010 | 0.00990 | 0.00700 | **0.00010** | "
            "0.04020 | – | – | 2200 | – |\n");
}

TEST(ResultsTable, LatexUsesBooktabsAndEscapesTheNames) {
  EXPECT_EQ(results_table_latex(two_runs()),
            "% ATE and RPE per run, written by slamkit eval compare; needs "
            "\\usepackage{booktabs}\n"
            "\\begin{tabular}{lrrrrrrrrrr}\n"
            "\\toprule\n"
            " & \\multicolumn{6}{c}{ATE [m]} & \\multicolumn{2}{c}{RPE RMSE} & "
            "\\multicolumn{2}{c}{pairs} \\\\\n"
            "\\cmidrule(lr){2-7} \\cmidrule(lr){8-9} \\cmidrule(lr){10-11}\n"
            "Run & RMSE & mean & median & std & min & max & trans. [m] & rot. [$^\\circ$] & ATE & "
            "RPE \\\\\n"
            "\\midrule\n"
            "orb\\_slam \\& co & \\textbf{0.00814} & \\textbf{0.00710} & \\textbf{0.00650} & "
            "\\textbf{0.00390} & 0.00020 & \\textbf{0.02510} & 0.00716 & 0.457 & 2223 & 1998 \\\\\n"
            "mine\\textbar{}v2, \\#1 50\\% & 0.01230 & 0.01010 & 0.00990 & 0.00700 & "
            "\\textbf{0.00010} & 0.04020 & -- & -- & 2200 & -- \\\\\n"
            "\\bottomrule\n"
            "\\end{tabular}\n");
}

// Metre-scale errors (KITTI) get 3 decimals for the 0.988 m RPE, degrees 2; a single run has
// no best to mark.
TEST(ResultsTable, LargerErrorsGetFewerDecimalsAndASingleRunNoBold) {
  const std::string table = results_table_markdown(
      {run("kitti~run",
           R"({"ate": {"pairs": 1101, "rmse": 12.345, "mean": 10.5, "median": 9.99, "std": 6.5,
                       "min": 0.25, "max": 30.125},
               "rpe": {"pairs": 1100, "trans": {"rmse": 0.9876}, "rot_deg": {"rmse": 1.25}}})")});
  EXPECT_NE(table.find("| kitti~run | 12.345 | 10.500 | 9.990 | 6.500 | 0.250 | 30.125 | 0.988 | "
                       "1.25 | 1101 | 1100 |"),
            std::string::npos)
      << table;
}

TEST(ResultsTable, TheThreeFilesAreWrittenIntoTheFolder) {
  const std::filesystem::path dir = test::temp_dir("results_table");
  write_results_tables(dir, two_runs());
  EXPECT_EQ(test::read_text(dir / "table.csv"), results_table_csv(two_runs()));
  EXPECT_EQ(test::read_text(dir / "table.md"), results_table_markdown(two_runs()));
  EXPECT_EQ(test::read_text(dir / "table.tex"), results_table_latex(two_runs()));
}

}  // namespace
}  // namespace slamkit::eval
