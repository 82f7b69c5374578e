#pragma once
// Points on the surface of a triangle mesh, so that a mesh is judged like a point-cloud map
// (map-eval): its surface, not only its vertices, must lie on the true one and cover it.
// Deterministic (no randomness; the same mesh gives the same points in the same order) and
// area-proportional: about one sample per spacing^2 of area.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace slamkit::eval {

using Triangle = std::array<uint32_t, 3>;  // vertex indices

// Each vertex the triangles use, once and in index order (vertices no triangle uses are left
// out), then each triangle's samples: rows parallel to its longest edge, at most `spacing`
// apart, from that edge to the opposite corner, with samples along each row at most
// `spacing` apart and at both of its ends (an edge two triangles share may be sampled twice).
// No point of a triangle is farther than 1.12 x spacing from a sample. Vertices must be
// finite, indices valid (read_ply_cloud checks them) and spacing positive; for a mesh from a
// file, ask mesh_sample_count first.
std::vector<Eigen::Vector3f> sample_mesh_surface(const std::vector<Eigen::Vector3f>& vertices,
                                                 const std::vector<Triangle>& triangles,
                                                 double spacing);

// For each vertex, whether a triangle uses it.
std::vector<bool> used_vertices(size_t vertex_count, const std::vector<Triangle>& triangles);

// How many points sample_mesh_surface would return, counted without making them (to refuse
// a mesh too large to sample before allocating); stops counting past `limit`.
uint64_t mesh_sample_count(const std::vector<Eigen::Vector3f>& vertices,
                           const std::vector<Triangle>& triangles, double spacing, uint64_t limit);

}  // namespace slamkit::eval
