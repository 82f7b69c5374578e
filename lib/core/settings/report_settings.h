#pragma once
// The report page `slamkit run` writes (RUN/report.html; docs/usage.md#slamkit-report).

namespace slamkit {

struct ReportSettings {
  bool enabled = true;  // (slamkit) `run` writes report.html once the run folder is complete
  // (slamkit) Map points drawn in the page at most, an even subset of map.ply: about 9 bytes
  // (12 as base64) each, so 300,000 keep a page near 4 MB and smooth in a browser.
  int point_budget = 300'000;
  // (slamkit) Triangles of mesh.ply drawn in the page at most, simplified by vertex clustering
  // when it has more: about 16 bytes (22 as base64) each with its share of the vertices, so
  // 300,000 add about 7 MB; 0 leaves the mesh out.
  int mesh_triangle_budget = 300'000;
};

}  // namespace slamkit
