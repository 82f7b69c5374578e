// slamkit report RUN... --out FILE.html: one self-contained page for a run folder, or comparing
// several (eval/report/report_page.h). `slamkit run` writes RUN/report.html the same way.
#include <cstdio>
#include <memory>

#include "bin/command.h"
#include "bin/output_folder.h"
#include "bin/report_writing.h"
#include "core/settings/report_settings.h"

namespace slamkit::cli {
namespace {

struct ReportArgs {
  std::vector<std::string> runs;
  std::string out;
  ReportSettings budgets;  // its point and triangle budgets
};

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<ReportArgs>();
  CLI::App* cmd = root.add_subcommand(
      "report",
      "One self-contained HTML page of run folders: the map in 3D, the trajectory coloured by "
      "error, groundtruth, keyframes, loops, lost frames, metrics, plots and per-frame "
      "diagnostics; several runs are compared on one page");
  cmd->add_option("runs", args->runs, "Run folders (slamkit run or track)")->required();
  cmd->add_option("--out", args->out, "The page to write (.html)")->required();
  cmd->add_option("--point-budget", args->budgets.point_budget,
                  "Map points in the page at most, shared among the runs (default 300000)")
      ->check(CLI::Range(0, 50'000'000));
  cmd->add_option("--mesh-triangle-budget", args->budgets.mesh_triangle_budget,
                  "Triangles of the runs' mesh.ply in the page at most, shared among them; "
                  "a mesh with more is simplified (default 300000, 0 = no mesh)")
      ->check(CLI::Range(0, 50'000'000));
  cmd->callback([args] {
    check_output_file("--out", args->out);
    std::vector<std::filesystem::path> runs(args->runs.begin(), args->runs.end());
    write_report_page(runs, args->out, args->budgets);
  });
});

}  // namespace
}  // namespace slamkit::cli
