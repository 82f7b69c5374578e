#pragma once
// The figure options of every command that draws figures (eval, run, track): which files, and
// the PNG's resolution.
#include <CLI/CLI.hpp>

#include "eval/plotting.h"

namespace slamkit::cli {

// --plot-format png|svg|pdf (repeated or comma-separated), --pdf, --dpi N.
void add_figure_options(CLI::App* cmd, eval::FigureFiles& files);

}  // namespace slamkit::cli
