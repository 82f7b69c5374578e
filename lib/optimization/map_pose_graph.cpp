#include "optimization/map_pose_graph.h"

namespace slamkit {

PoseGraph essential_graph(const Map& map, const std::vector<LoopConstraint>& loops,
                          const EssentialGraphOptions& options) {
  PoseGraph graph;
  const int n = int(map.keyframes().size());
  graph.fixed.assign(size_t(n), false);
  if (n > 0) graph.fixed[0] = true;
  for (const Keyframe& k : map.keyframes()) graph.T_w_c.push_back(k.T_w_c);
  const auto current_edge = [&](int from, int to) {
    return PoseGraphEdge{from, to, map.keyframe(from).T_c_w * map.keyframe(to).T_w_c, 1};
  };
  for (int k = 1; k < n; ++k) {
    const Keyframe& keyframe = map.keyframe(k);
    if (keyframe.parent >= 0) graph.edges.push_back(current_edge(keyframe.parent, k));
    // Each strong covisibility pair once, from the older keyframe; the parent's edge is there.
    for (int other : keyframe.covisible) {
      if (other >= k || other == keyframe.parent) continue;
      const auto shared = keyframe.shared_points.find(other);
      if (shared != keyframe.shared_points.end() &&
          shared->second >= options.min_covisibility_weight)
        graph.edges.push_back(current_edge(other, k));
    }
  }
  for (const LoopConstraint& loop : loops) {
    graph.edges.push_back({loop.keyframe, loop.loop_keyframe, loop.T_keyframe_loop, 1});
    graph.fixed[size_t(loop.loop_keyframe)] = true;
  }
  return graph;
}

PoseGraphReport correct_loops(Map& map, const std::vector<LoopConstraint>& loops,
                              const EssentialGraphOptions& options) {
  PoseGraph graph = essential_graph(map, loops, options);
  const PoseGraphReport report = optimise_pose_graph(graph, options.iterations);
  if (!report.solved) return report;
  std::vector<Eigen::Isometry3d> T_w_c_before;
  for (const Keyframe& k : map.keyframes()) T_w_c_before.push_back(k.T_w_c);
  for (size_t k = 0; k < graph.T_w_c.size(); ++k) map.set_keyframe_pose(int(k), graph.T_w_c[k]);
  for (size_t id = 0; id < size_t(map.num_point_ids()); ++id) {
    const MapPoint& p = map.point(int(id));
    if (p.bad) continue;
    const int r = p.reference_keyframe;
    map.set_point_position(int(id), graph.T_w_c[size_t(r)] *
                                        (T_w_c_before[size_t(r)].inverse() * p.p_w));
    map.update_point_geometry(int(id));
  }
  return report;
}

}  // namespace slamkit
