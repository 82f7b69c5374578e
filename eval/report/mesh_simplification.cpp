#include "eval/report/mesh_simplification.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "fusion/flat_hash_map.h"
#include "fusion/voxel_key.h"

namespace slamkit::eval {
namespace {

using Triangle = std::array<uint32_t, 3>;

double surface_area(const PlyCloud& mesh) {
  double area = 0;
  for (const Triangle& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.points[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.points[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.points[t[2]].cast<double>();
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

struct Clusters {
  std::vector<uint32_t> of_vertex;
  size_t count = 0;
};

// Each vertex's cell on a grid of `cell` metres from `low`, the cells numbered in the order of
// their first vertex (FlatHashMap keeps insertion order), so the numbering is the mesh's own.
Clusters cluster_by_cell(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& low,
                         float cell) {
  FlatHashMap<uint32_t> cells;
  Clusters clusters;
  clusters.of_vertex.reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    const Eigen::Array3i index = ((p - low) / cell).array().floor().cast<int>();
    const size_t known = cells.size();
    uint32_t& number = cells[voxel_key(index)];
    if (cells.size() > known) number = uint32_t(known);
    clusters.of_vertex.push_back(number);
  }
  clusters.count = cells.size();
  return clusters;
}

// The triangles between clusters that keep three distinct vertices.
std::vector<Triangle> collapse(const std::vector<Triangle>& triangles,
                               const std::vector<uint32_t>& cluster) {
  std::vector<Triangle> kept;
  for (const Triangle& t : triangles) {
    const Triangle c = {cluster[t[0]], cluster[t[1]], cluster[t[2]]};
    if (c[0] != c[1] && c[1] != c[2] && c[2] != c[0]) kept.push_back(c);
  }
  return kept;
}

// Each set of three vertices once, the first triangle over it kept: neighbouring triangles can
// collapse onto the same three, and so do the two sides of a part thinner than a cell. Only one
// side of such a part is kept: two opposite windings over the same vertices would cancel their
// normals, which the page computes per vertex, and it would draw the part black.
std::vector<Triangle> without_repeats(const std::vector<Triangle>& triangles) {
  std::vector<std::pair<Triangle, size_t>> sorted(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    sorted[i] = {triangles[i], i};
    std::sort(sorted[i].first.begin(), sorted[i].first.end());
  }
  std::sort(sorted.begin(), sorted.end());  // the same vertices together, in the mesh's order
  std::vector<bool> first(triangles.size(), false);
  for (size_t k = 0; k < sorted.size(); ++k)
    if (k == 0 || sorted[k].first != sorted[k - 1].first) first[sorted[k].second] = true;
  std::vector<Triangle> unique;
  for (size_t i = 0; i < triangles.size(); ++i)
    if (first[i]) unique.push_back(triangles[i]);
  return unique;
}

// The mesh of the clusters the triangles use, each at the mean position and colour of its
// vertices, numbered in the order the triangles first use them.
PlyCloud clustered_mesh(const PlyCloud& mesh, const Clusters& clusters,
                        const std::vector<Triangle>& triangles) {
  std::vector<Eigen::Vector3d> position_sum(clusters.count, Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> colour_sum(clusters.count, Eigen::Vector3d::Zero());
  std::vector<uint32_t> members(clusters.count, 0);
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    const uint32_t c = clusters.of_vertex[i];
    position_sum[c] += mesh.points[i].cast<double>();
    for (int k = 0; k < 3; ++k) colour_sum[c][k] += mesh.colours[i][k];
    ++members[c];
  }
  constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> renumbered(clusters.count, kUnused);
  PlyCloud out;
  out.triangles.reserve(triangles.size());
  for (const Triangle& t : triangles) {
    Triangle& renumbered_triangle = out.triangles.emplace_back();
    for (int k = 0; k < 3; ++k) {
      const uint32_t c = t[k];
      if (renumbered[c] == kUnused) {
        renumbered[c] = uint32_t(out.points.size());
        out.points.push_back((position_sum[c] / members[c]).cast<float>());
        const Eigen::Vector3d colour = colour_sum[c] / members[c];
        out.colours.push_back({uint8_t(std::lround(colour[0])), uint8_t(std::lround(colour[1])),
                               uint8_t(std::lround(colour[2]))});
      }
      renumbered_triangle[k] = renumbered[c];
    }
  }
  return out;
}

}  // namespace

PlyCloud simplify_mesh(const PlyCloud& mesh, size_t budget) {
  if (mesh.triangles.size() <= budget) return mesh;
  if (budget == 0) return {};
  Eigen::Vector3f low = mesh.points.front(), high = low;
  for (const Eigen::Vector3f& p : mesh.points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // The grid's indices stay below 2^19, within the cell key's range (voxel_key.h).
  const float finest = std::max((high - low).maxCoeff(), 1e-3f) / float(1 << 19);
  // A surface of area A crosses about A / c² cells of side c, each a vertex of about two
  // triangles.
  float cell = std::max(finest, float(std::sqrt(2 * surface_area(mesh) / double(budget))));
  Clusters clusters;
  std::vector<Triangle> triangles;
  while (true) {
    clusters = cluster_by_cell(mesh.points, low, cell);
    triangles = collapse(mesh.triangles, clusters.of_vertex);
    if (triangles.size() <= budget) break;
    // The triangles go as 1 / c²; at least 5 % coarser, so that the grid reaches one cell.
    cell *= std::max(1.05f, std::sqrt(float(triangles.size()) / float(budget)));
  }
  return clustered_mesh(mesh, clusters, without_repeats(triangles));
}

}  // namespace slamkit::eval
