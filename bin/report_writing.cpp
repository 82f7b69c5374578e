#include "bin/report_writing.h"

#include <cstdio>
#include <string>

#include "bin/build_info.h"
#include "core/stopwatch.h"
#include "eval/report/report_page.h"

namespace slamkit::cli {

void write_report_page(const std::vector<std::filesystem::path>& runs,
                       const std::filesystem::path& out, const ReportSettings& budgets,
                       bool quiet) {
  Stopwatch watch;
  eval::ReportOptions options;
  options.point_budget = size_t(budgets.point_budget);
  options.mesh_triangle_budget = size_t(budgets.mesh_triangle_budget);
  options.generator = std::string("slamkit ") + kVersion + " (" + kCommit + ")";
  const eval::ReportSummary summary = eval::write_report(runs, out, options);
  if (quiet) return;
  for (const std::string& note : summary.notes) std::fprintf(stderr, "report: %s\n", note.c_str());
  std::string mesh;
  if (summary.mesh_triangles > 0)
    mesh = ", " + std::to_string(summary.mesh_triangles_shown) + " of " +
           std::to_string(summary.mesh_triangles) + " mesh triangles";
  std::printf("report      %s: %.1f MB, %zu of %zu map points%s, %.2f s\n", out.c_str(),
              double(summary.bytes) / 1e6, summary.map_points_shown, summary.map_points,
              mesh.c_str(), watch.lap() / 1000);
}

}  // namespace slamkit::cli
