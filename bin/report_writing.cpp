#include "bin/report_writing.h"

#include <cstdio>
#include <string>

#include "bin/build_info.h"
#include "core/stopwatch.h"
#include "eval/report/report_page.h"

namespace slamkit::cli {

void write_report_page(const std::vector<std::filesystem::path>& runs,
                       const std::filesystem::path& out, size_t point_budget) {
  Stopwatch watch;
  eval::ReportOptions options;
  options.point_budget = point_budget;
  options.generator = std::string("slamkit ") + kVersion + " (" + kCommit + ")";
  const eval::ReportSummary summary = eval::write_report(runs, out, options);
  for (const std::string& note : summary.notes) std::fprintf(stderr, "report: %s\n", note.c_str());
  std::printf("report      %s: %.1f MB, %zu of %zu map points, %.2f s\n", out.c_str(),
              double(summary.bytes) / 1e6, summary.map_points_shown, summary.map_points,
              watch.lap() / 1000);
}

}  // namespace slamkit::cli
