#pragma once
// A triangle mesh for the report's tests: a sphere coloured by position.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "fusion/ply_cloud.h"

namespace slamkit::test {

// Red, green and blue grow along x, y and z over the box centre ± radius: a linear function of
// position, so a vertex merged from others has the colour of their mean position.
inline Rgb8 colour_by_position(const Eigen::Vector3f& p, const Eigen::Vector3f& centre,
                               float radius) {
  Rgb8 colour;
  for (int d = 0; d < 3; ++d)
    colour[d] = uint8_t(
        std::lround(255 * std::clamp((p[d] - centre[d] + radius) / (2 * radius), 0.0f, 1.0f)));
  return colour;
}

// A UV sphere: `rings` bands from pole to pole of `segments` vertices each, 2 * segments *
// (rings - 1) triangles counter-clockwise seen from outside, as a TSDF's surface faces the free
// space it was seen from.
inline PlyCloud sphere_mesh(int rings, int segments, const Eigen::Vector3f& centre, float radius) {
  PlyCloud mesh;
  const auto add_vertex = [&](float polar, float azimuth) {
    const Eigen::Vector3f p =
        centre + radius * Eigen::Vector3f(std::sin(polar) * std::cos(azimuth),
                                          std::sin(polar) * std::sin(azimuth), std::cos(polar));
    mesh.points.push_back(p);
    mesh.colours.push_back(colour_by_position(p, centre, radius));
  };
  const float pi = float(M_PI);
  add_vertex(0, 0);  // the north pole, vertex 0
  for (int ring = 1; ring < rings; ++ring)
    for (int s = 0; s < segments; ++s) add_vertex(pi * ring / rings, 2 * pi * s / segments);
  add_vertex(pi, 0);  // the south pole, the last vertex
  const auto at = [&](int ring, int s) {
    return uint32_t(1 + (ring - 1) * segments + s % segments);
  };
  const uint32_t south = uint32_t(mesh.points.size() - 1);
  for (int s = 0; s < segments; ++s) {
    mesh.triangles.push_back({0, at(1, s), at(1, s + 1)});
    for (int ring = 1; ring + 1 < rings; ++ring) {
      mesh.triangles.push_back({at(ring, s), at(ring + 1, s), at(ring + 1, s + 1)});
      mesh.triangles.push_back({at(ring, s), at(ring + 1, s + 1), at(ring, s + 1)});
    }
    mesh.triangles.push_back({south, at(rings - 1, s + 1), at(rings - 1, s)});
  }
  return mesh;
}

}  // namespace slamkit::test
