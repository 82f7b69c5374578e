#include "loop/loop_fusion.h"

#include <set>

#include "mapping/duplicate_fusion.h"

namespace slamkit {
namespace {

// The keyframe and its covisible neighbours (all of them, as ORB-SLAM2's loop neighbourhoods).
std::vector<int> with_neighbours(const Map& map, int keyframe) {
  std::vector<int> group = map.best_covisible(keyframe, 0);
  group.insert(group.begin(), keyframe);
  return group;
}

}  // namespace

int fuse_loop_points(Map& map, const std::vector<LoopConstraint>& loops, const Camera& camera,
                     const Settings& settings) {
  FusionGates gates;
  gates.radius = settings.loop.fuse_radius;
  gates.max_distance = settings.mapping.fuse_max_distance;
  gates.min_view_cos = settings.mapping.min_view_cos;
  gates.chi2_2d = settings.optimization.residual.chi2_2d;
  gates.chi2_3d = settings.optimization.residual.chi2_3d;
  gates.virtual_bf = settings.optimization.residual.virtual_bf;
  int fused = 0;
  for (const LoopConstraint& loop : loops) {
    std::vector<int> loop_points;
    std::set<int> seen;
    for (int k : with_neighbours(map, loop.loop_keyframe))
      for (int id : map.keyframe(k).point_ids)
        if (id >= 0 && !map.point(id).bad && seen.insert(id).second) loop_points.push_back(id);
    const std::vector<int> group = with_neighbours(map, loop.keyframe);
    for (int k : group) fused += int(fuse_into_keyframe(map, k, loop_points, camera, gates).size());
    for (int k : group) map.update_connections(k);
  }
  return fused;
}

}  // namespace slamkit
