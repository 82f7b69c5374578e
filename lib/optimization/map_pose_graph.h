#pragma once
// Loop correction on the map (docs/method.md#loop-closing; ORB-SLAM2's OptimizeEssentialGraph,
// in SE(3)): the essential graph (spanning tree, strong covisibility, loop edges) built from
// the map's current poses, optimised as a pose graph, and the result applied: every keyframe
// moves, and every point moves with its reference keyframe. The global BA runs after it.
#include <Eigen/Geometry>
#include <vector>

#include "map/map.h"
#include "optimization/pose_graph.h"

namespace slamkit {

// A detected loop: `loop_keyframe` (the older, revisited place) as seen from `keyframe`,
// measured by matching the two (the RANSAC-SVD pose the loop check accepted).
struct LoopConstraint {
  int keyframe = -1;
  int loop_keyframe = -1;
  Eigen::Isometry3d T_keyframe_loop = Eigen::Isometry3d::Identity();
};

struct EssentialGraphOptions {
  int min_covisibility_weight = 100;  // (ORB-SLAM2) covisibility edges sharing this many points
  int iterations = 20;                // (ORB-SLAM2) LM iterations
};

// The essential graph of `map` with `loops` added, as pose-graph data: one node per keyframe
// at its current pose, keyframe 0 and every loop_keyframe fixed (ORB-SLAM2 fixes the loop's
// old side), edges at the current relative poses except the loop edges.
PoseGraph essential_graph(const Map& map, const std::vector<LoopConstraint>& loops,
                          const EssentialGraphOptions& options);

// Optimises the essential graph and moves keyframes and points (each with its reference
// keyframe's correction). The map is unchanged when the graph could not be solved.
PoseGraphReport correct_loops(Map& map, const std::vector<LoopConstraint>& loops,
                              const EssentialGraphOptions& options);

}  // namespace slamkit
