#include "eval/run/map_points.h"

#include <cstdio>
#include <string>

#include "core/error.h"
#include "eval/run/mesh_sampling.h"
#include "fusion/ply_cloud.h"

namespace slamkit::eval {
namespace {

std::string coordinates(const Eigen::Vector3f& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return text;
}

// The vertices judged: all of a cloud's, only those a mesh's faces use.
std::vector<bool> judged_vertices(const PlyCloud& cloud) {
  if (cloud.triangles.empty()) return std::vector<bool>(cloud.points.size(), true);
  return used_vertices(cloud.points.size(), cloud.triangles);
}

// Numbers computed from such points would look like a result and mean nothing.
void check_points(const PlyCloud& cloud, const std::string& name) {
  const std::vector<bool> judged = judged_vertices(cloud);
  const Eigen::Vector3f* first = nullptr;
  bool all_at_first = true;
  size_t count = 0;
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (!judged[i]) continue;
    const Eigen::Vector3f& p = cloud.points[i];
    if (!p.allFinite())
      throw_input_error(name, "vertex " + std::to_string(i) + " is not finite " + coordinates(p) +
                                  ": a map's points must be");
    if (!first) first = &p;
    all_at_first = all_at_first && p == *first;
    ++count;
  }
  if (count == 0) throw_input_error(name, "the map has no point to judge");
  if (all_at_first)
    throw_input_error(name, "all " + std::to_string(count) + " points of the map are at " +
                                coordinates(*first) + ": not a map to judge");
}

}  // namespace

MapPoints read_map_points(const std::filesystem::path& ply) {
  const std::string name = ply.string();
  PlyCloud cloud = read_ply_cloud(ply);
  check_points(cloud, name);
  MapPoints map;
  if (cloud.triangles.empty()) {
    map.points = std::move(cloud.points);
    return map;
  }
  const uint64_t samples =
      mesh_sample_count(cloud.points, cloud.triangles, kMeshSampleSpacing, kMaxMeshSamples);
  if (samples > kMaxMeshSamples) {
    char why[160];
    std::snprintf(why, sizeof why,
                  "the mesh's surface needs more than %llu samples %.1f mm apart: too large for "
                  "map-eval (not in metres?)",
                  (unsigned long long)kMaxMeshSamples, 1000 * kMeshSampleSpacing);
    throw_input_error(name, why);
  }
  map.points = sample_mesh_surface(cloud.points, cloud.triangles, kMeshSampleSpacing);
  map.mesh_triangles = cloud.triangles.size();
  return map;
}

}  // namespace slamkit::eval
