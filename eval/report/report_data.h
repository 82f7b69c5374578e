#pragma once
// The data a report page draws, as one JSON object embedded in the page: per run its metrics,
// settings and stage times (as the run folder holds them), and its geometry as base64 arrays in
// one frame, the groundtruth's when the run was evaluated (so that several runs of a sequence
// overlay), else the estimate's own. The map is an evenly strided subset of at most the point
// budget, its positions quantised to 16 bits over its bounding box (0.1 mm in a 6 m room); the
// mesh, when a run has one, is simplified to at most the triangle budget
// (eval/report/mesh_simplification.h), its vertices quantised the same way.
#include <nlohmann/json.hpp>
#include <vector>

#include "core/settings/report_settings.h"
#include "eval/report/run_folder.h"
#include "fusion/ply_cloud.h"

namespace slamkit::eval {

// The indices of at most `budget` of `total` points, evenly spread over the file's order: the
// fused map is written voxel by voxel, so a stride keeps the whole map at a lower density. The
// same map gives the same subset.
std::vector<size_t> strided_subset(size_t total, size_t budget);

struct ReportOptions {
  // Map points in the page, shared out among the runs' maps.
  size_t point_budget = size_t(ReportSettings{}.point_budget);
  // Mesh triangles in the page, shared out among the runs' meshes; 0 leaves them out.
  size_t mesh_triangle_budget = size_t(ReportSettings{}.mesh_triangle_budget);
  std::string generator;  // "slamkit VERSION", shown in the footer
};

// `maps[i]` and `meshes[i]` are runs[i]'s map.ply and mesh.ply read whole (empty when it has
// none).
nlohmann::json report_data(const std::vector<RunFolder>& runs, const std::vector<PlyCloud>& maps,
                           const std::vector<PlyCloud>& meshes, const ReportOptions& options);

}  // namespace slamkit::eval
