#pragma once
// `slamkit report`: one self-contained HTML page for one run folder, or comparing several: the
// map in 3D with the trajectories coloured by error, the groundtruth, keyframes, loops and lost
// frames; the metrics, the evaluator's plots and the per-frame diagnostics (docs/usage.md#report).
// The page holds everything it shows, three.js included, and fetches nothing (its
// Content-Security-Policy forbids it).
#include <filesystem>
#include <string>
#include <vector>

#include "eval/report/report_data.h"

namespace slamkit::eval {

// The page's HTML around `data` (report_data's JSON).
std::string render_report_page(const nlohmann::json& data, const std::string& title);

struct ReportSummary {
  size_t bytes = 0;
  size_t map_points = 0, map_points_shown = 0;          // over every run's map
  size_t mesh_triangles = 0, mesh_triangles_shown = 0;  // over the meshes the page shows
  std::vector<std::string> notes;  // per run: what it lacks ("desk: no map.ply...")
};

// Reads the run folders (eval/report/run_folder.h) and writes the page to `out`, atomically.
// Throws InputError naming the file for a folder that is not a run folder or holds a malformed
// file, and when `out` cannot be written.
ReportSummary write_report(const std::vector<std::filesystem::path>& runs,
                           const std::filesystem::path& out, const ReportOptions& options);

}  // namespace slamkit::eval
