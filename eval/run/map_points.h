#pragma once
// The points map-eval judges in a PLY map, a run's map.ply or another system's cloud or mesh:
// a point cloud's vertices, or samples of a mesh's surface (mesh_sampling.h).
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace slamkit::eval {

inline constexpr double kMeshSampleSpacing = 0.0025;  // metres between samples, at most
// 50 million samples (600 MB) cover 300 m^2 of surface: a room is far less.
inline constexpr uint64_t kMaxMeshSamples = 50'000'000;

struct MapPoints {
  std::vector<Eigen::Vector3f> points;
  size_t mesh_triangles = 0;  // 0: the file is a point cloud, `points` its vertices
};

// Throws InputError naming the file when read_ply_cloud does, when it has no vertex, when a
// point is not finite (naming the first such vertex), when all points are at one place (what
// a reader that missed the coordinates makes: not a map), or when a mesh would need more
// than kMaxMeshSamples samples. A mesh's vertices that no face uses are ignored.
MapPoints read_map_points(const std::filesystem::path& ply);

}  // namespace slamkit::eval
