#include "bin/figure_options.h"

namespace slamkit::cli {

void add_figure_options(CLI::App* cmd, eval::FigureFiles& files) {
  // One value per --plot-format, so that a list cannot swallow the positional arguments after it.
  cmd->add_option("--plot-format", files.formats,
                  "Figure files: png, svg or pdf, repeated or comma-separated (default: png,svg)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember({"png", "svg", "pdf"}));
  cmd->add_flag("--pdf", files.pdf, "Also write PDF figures (with the default: png, svg and pdf)");
  cmd->add_option("--dpi", files.dpi, "Resolution of PNG figures in dots per inch (default 200)")
      ->check(CLI::Range(10, 2400));
}

}  // namespace slamkit::cli
