#include "eval/run/mesh_sampling.h"

#include <algorithm>
#include <cmath>

namespace slamkit::eval {
namespace {

// A triangle as its longest edge a-b and the corner c opposite. Rows run parallel to a-b:
// row k lies k / rows of the way from a-b to c, from a point of a-c to a point of b-c. The
// corners at a and b are at most 90 degrees (the longest edge faces the largest angle), so
// each row spans the rows above it: a point between two rows lies within `spacing` of the
// lower row, beside it between two samples at most `spacing` apart, hence within
// sqrt(1 + 1/4) = 1.12 x spacing of one of them.
struct Rows {
  Eigen::Vector3d a, b, c;
  double rows = 1;  // c itself, row `rows`, is a vertex sample
};

Rows rows_of(const Eigen::Vector3f& p0, const Eigen::Vector3f& p1, const Eigen::Vector3f& p2,
             double spacing) {
  const Eigen::Vector3d v[3] = {p0.cast<double>(), p1.cast<double>(), p2.cast<double>()};
  int longest = 0;  // edge i runs from v[i] to v[(i + 1) % 3]
  double longest_length = -1;
  for (int i = 0; i < 3; ++i) {
    const double length = (v[(i + 1) % 3] - v[i]).norm();
    if (length > longest_length) longest = i, longest_length = length;
  }
  Rows t{v[longest], v[(longest + 1) % 3], v[(longest + 2) % 3]};
  const double height =
      longest_length > 0 ? (t.c - t.a).cross(t.b - t.a).norm() / longest_length : 0.0;
  t.rows = std::max(1.0, std::ceil(height / spacing));
  return t;
}

// Intervals of at most `spacing` along a row of this length.
double intervals(double length, double spacing) {
  return std::max(1.0, std::ceil(length / spacing));
}

// The ends of row k.
std::pair<Eigen::Vector3d, Eigen::Vector3d> row_ends(const Rows& t, double k) {
  const double s = k / t.rows;
  return {t.a + s * (t.c - t.a), t.b + s * (t.c - t.b)};
}

}  // namespace

std::vector<bool> used_vertices(size_t vertex_count, const std::vector<Triangle>& triangles) {
  std::vector<bool> used(vertex_count, false);
  for (const Triangle& triangle : triangles)
    for (const uint32_t index : triangle) used[index] = true;
  return used;
}

std::vector<Eigen::Vector3f> sample_mesh_surface(const std::vector<Eigen::Vector3f>& vertices,
                                                 const std::vector<Triangle>& triangles,
                                                 double spacing) {
  std::vector<Eigen::Vector3f> samples;
  const std::vector<bool> used = used_vertices(vertices.size(), triangles);
  for (size_t i = 0; i < vertices.size(); ++i)
    if (used[i]) samples.push_back(vertices[i]);
  for (const Triangle& triangle : triangles) {
    const Rows t =
        rows_of(vertices[triangle[0]], vertices[triangle[1]], vertices[triangle[2]], spacing);
    for (double k = 0; k < t.rows; ++k) {
      const auto [p, q] = row_ends(t, k);
      const double n = intervals((q - p).norm(), spacing);
      const bool base = k == 0;  // from vertex a to vertex b, both sampled above
      for (double i = base ? 1 : 0; i <= (base ? n - 1 : n); ++i)
        samples.push_back((p + (i / n) * (q - p)).cast<float>());
    }
  }
  return samples;
}

uint64_t mesh_sample_count(const std::vector<Eigen::Vector3f>& vertices,
                           const std::vector<Triangle>& triangles, double spacing, uint64_t limit) {
  const std::vector<bool> used = used_vertices(vertices.size(), triangles);
  double count = double(std::count(used.begin(), used.end(), true));
  for (const Triangle& triangle : triangles) {
    const Rows t =
        rows_of(vertices[triangle[0]], vertices[triangle[1]], vertices[triangle[2]], spacing);
    if (t.rows > double(limit)) return limit + 1;
    for (double k = 0; k < t.rows && count <= double(limit); ++k) {
      const auto [p, q] = row_ends(t, k);
      count += intervals((q - p).norm(), spacing) + (k == 0 ? -1 : 1);
    }
    if (count > double(limit)) return limit + 1;
  }
  return uint64_t(count);
}

}  // namespace slamkit::eval
