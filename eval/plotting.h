#pragma once
// Plots are drawn by matplotlib scripts next to this file (plot_trajectory_errors.py,
// plot_compare.py) from the data files the C++ side wrote; this finds a Python that has
// matplotlib and runs them.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamkit::eval {

struct PlotPython {
  std::optional<std::string> interpreter;  // set when it can import matplotlib
  std::string problem;                     // why not, for the user
};

// $SLAMKIT_PYTHON, else /usr/bin/python3 (Debian's, which has matplotlib; the python3 on
// PATH may be another build without it).
PlotPython find_plot_python();

// $SLAMKIT_EVAL_SCRIPTS/<name>, else the source folder of eval/.
std::filesystem::path plot_script(const std::string& name);

// Runs `interpreter script args...` without a shell; returns its exit code (-1 if it could
// not start).
int run_program(const std::string& interpreter, const std::vector<std::string>& args,
                bool silence_output = false);

// Runs the plot script `script` (plot_script) with `args` under find_plot_python(). Returns
// `png` once it exists, else nothing, with a note on stderr saying why no `what` was drawn
// (no interpreter with matplotlib, or the script failed).
std::optional<std::filesystem::path> draw_plot(const std::string& script,
                                               const std::vector<std::string>& args,
                                               const std::filesystem::path& png,
                                               const std::string& what);

}  // namespace slamkit::eval
