#pragma once
// Plots are drawn by eval/plot.py from the data files the C++ side wrote (metrics.json, the
// CSVs), so metrics cost nothing when plots are off. One Python process draws every figure a
// command asks for: starting Python and importing matplotlib costs about 0.4 s before any
// figure is drawn, which one process per figure paid again and again. plot.py then forks a
// child per figure, so the figures are drawn on every core with the imports paid once.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace slamkit::eval {

struct PlotOutcome {
  bool drawn = false;
  bool python_missing = false;  // no interpreter, or one without matplotlib
  std::string problem;          // why not drawn, for the user
  double seconds = 0;           // wall time of the plotting process
};

// Which figure files a command writes (--plot-format, --pdf, --dpi).
struct FigureFiles {
  std::vector<std::string> formats;  // png, svg, pdf; empty: png and svg
  bool pdf = false;                  // pdf as well
  int dpi = 0;                       // of PNGs; 0: the plot style's
};

// The "formats" and "dpi" fields of a figure request (plot_style.save): the formats as given
// (empty: png and svg, the files every command wrote before --plot-format existed) with pdf
// added for `pdf` (--pdf, the older spelling, which kept the PNG and SVG), each once; "dpi" only
// when not 0, else the style's 200.
nlohmann::json figure_files(const FigureFiles& files);

// Runs plot.py with `figures`, a JSON list of {"figure": KIND, ...} (see plot.py), under
// $SLAMKIT_PYTHON, else /usr/bin/python3 (Debian's, which has matplotlib; the python3 on
// PATH may be another build without it). plot.py is found as eval/plot_scripts.h says:
// $SLAMKIT_EVAL_SCRIPTS, else beside an installed binary, else in the source folder of eval/.
PlotOutcome draw_figures(const nlohmann::json& figures);

// Runs the plot script `script` (found as plot.py is) with `args` under the same interpreter.
// Returns `png` once it exists, else nothing, with a note on stderr saying why no `what` was
// drawn (the script failed, or could not import matplotlib: its exit code).
std::optional<std::filesystem::path> draw_plot(const std::string& script,
                                               const std::vector<std::string>& args,
                                               const std::filesystem::path& png,
                                               const std::string& what);

}  // namespace slamkit::eval
