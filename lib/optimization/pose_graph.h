#pragma once
// Pose-graph optimisation over keyframe poses (loop correction, docs/method.md#loop-closing;
// ORB-SLAM2's essential graph, in SE(3) since RGB-D fixes the scale): each edge measures the
// pose of one keyframe in another's frame; the poses move to agree with all edges at once,
// which spreads a loop's correction along the loop. Ceres with a quaternion manifold, as its
// pose_graph_3d example builds it. Plain data: the loop pass turns the map into this and back.
#include <Eigen/Geometry>
#include <vector>

namespace slamkit {

struct PoseGraphEdge {
  int from = -1, to = -1;
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();  // `to`'s pose in `from`'s frame
  // Weight of the edge's residual: the information matrix is weight x identity (ORB-SLAM2
  // gives every edge the identity; a loop edge may be weighted up).
  double weight = 1;
};

struct PoseGraph {
  std::vector<Eigen::Isometry3d> T_w_c;  // one per node, world-from-camera
  std::vector<bool> fixed;               // same size; at least one node fixed (the gauge)
  std::vector<PoseGraphEdge> edges;
};

struct PoseGraphReport {
  bool solved = false;  // false: nothing free or no edge, or Ceres failed (poses unchanged)
  int iterations = 0;
  double initial_cost = 0, final_cost = 0;  // 0.5 sum of squared weighted residuals
};

// Moves the free nodes of `graph` to minimise, over the edges, the squared residual
// (translation of the measured-versus-estimated relative pose, in metres, and twice the vector
// part of its rotation quaternion, about radians) times the weight. Levenberg-Marquardt, at
// most `iterations`, single-threaded: the same input gives bit-identical poses. Throws
// std::invalid_argument for an edge naming a node that does not exist or sizes that differ.
PoseGraphReport optimise_pose_graph(PoseGraph& graph, int iterations);

}  // namespace slamkit
