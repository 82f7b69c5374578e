#pragma once
// Maps that lie exactly on a synthetic scene's true surface, for the map-eval tests: the
// surface a camera sees as a grid of ray hits, a mesh over that grid, and the hits written as
// Open3D writes a point cloud (double coordinates).
#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/synth/scene.h"
#include "fusion/ply_cloud.h"

namespace slamkit::test {

// The scene seen from `pose` through every `stride`-th pixel, row by row; no hit beyond 3 m.
struct SurfaceGrid {
  int columns = 0, rows = 0;
  std::vector<std::optional<synth::SurfaceHit>> hits;  // row-major
};

inline SurfaceGrid surface_grid(const synth::SyntheticScene& scene, const Camera& camera,
                                const Eigen::Isometry3d& pose, int stride) {
  SurfaceGrid grid;
  for (int v = 0; v < camera.height; v += stride, ++grid.rows)
    for (int u = 0; u < camera.width; u += stride) {
      const Eigen::Vector3d ray = pose.linear() * camera.back_project({u, v}, 1.0);
      auto hit = scene.cast_ray(pose.translation(), ray);
      if (hit && hit->t > 3.0) hit.reset();  // t is the depth: the ray has z = 1
      grid.hits.push_back(hit);
    }
  grid.columns = int(grid.hits.size()) / grid.rows;
  return grid;
}

inline std::vector<synth::SurfaceHit> hits_of(const SurfaceGrid& grid) {
  std::vector<synth::SurfaceHit> hits;
  for (const auto& hit : grid.hits)
    if (hit) hits.push_back(*hit);
  return hits;
}

// The grid's hits as vertices, two triangles a grid cell where all three corners lie on one
// face of the scene: the mesh lies on the true surface.
inline PlyCloud mesh_on_surface(const SurfaceGrid& grid) {
  PlyCloud mesh;
  std::vector<uint32_t> index(grid.hits.size());
  for (size_t i = 0; i < grid.hits.size(); ++i)
    if (grid.hits[i]) {
      index[i] = uint32_t(mesh.points.size());
      mesh.points.push_back(grid.hits[i]->point.cast<float>());
      mesh.colours.push_back({128, 128, 128});
    }
  const auto add = [&](int a, int b, int c) {
    const auto& h = grid.hits;
    if (h[a] && h[b] && h[c] && h[a]->surface == h[b]->surface && h[a]->surface == h[c]->surface)
      mesh.triangles.push_back({index[a], index[b], index[c]});
  };
  for (int r = 0; r + 1 < grid.rows; ++r)
    for (int c = 0; c + 1 < grid.columns; ++c) {
      const int i = r * grid.columns + c;
      add(i, i + 1, i + grid.columns);
      add(i + 1, i + grid.columns + 1, i + grid.columns);
    }
  return mesh;
}

// Open3D's layout for a point cloud: double x y z, double nx ny nz, uchar red green blue,
// binary little-endian (the test machines are little-endian).
inline void write_open3d_like_ply(const std::filesystem::path& path,
                                  const std::vector<synth::SurfaceHit>& hits) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\ncomment Created by Open3D\nelement vertex "
      << hits.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty double nx\n"
         "property double ny\nproperty double nz\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nend_header\n";
  for (const synth::SurfaceHit& hit : hits) {
    out.write(reinterpret_cast<const char*>(hit.point.data()), 3 * sizeof(double));
    out.write(reinterpret_cast<const char*>(hit.normal.data()), 3 * sizeof(double));
    out.write("\x80\x80\x80", 3);
  }
}

// The same points as write_ply_cloud writes them (float coordinates, no normals).
inline void write_float_ply(const std::filesystem::path& path,
                            const std::vector<synth::SurfaceHit>& hits) {
  PlyCloud cloud;
  for (const synth::SurfaceHit& hit : hits) {
    cloud.points.push_back(hit.point.cast<float>());
    cloud.colours.push_back({128, 128, 128});
  }
  write_ply_cloud(path, cloud);
}

}  // namespace slamkit::test
