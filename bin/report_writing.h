#pragma once
// Writes a report page and prints what it holds (`slamkit report`, and `run` at its end).
#include <filesystem>
#include <vector>

#include "core/settings/report_settings.h"

namespace slamkit::cli {

// Prints the notes of what the runs lack on stderr ("report: desk: no map.ply: ..."), then one
// line: the page, its size, the map points (and mesh triangles) shown and the seconds it took;
// nothing when `quiet`. `budgets`: the point and triangle budgets.
void write_report_page(const std::vector<std::filesystem::path>& runs,
                       const std::filesystem::path& out, const ReportSettings& budgets,
                       bool quiet = false);

}  // namespace slamkit::cli
