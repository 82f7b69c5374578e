#pragma once
// Map upkeep at each new keyframe (ORB-SLAM2's LocalMapping, ORBSLAM2_BACKEND.md sections 1-2).

namespace slamkit {

struct MappingSettings {
  int covisibility_min_shared = 15;  // (ORB-SLAM2) keyframes sharing this many points are linked
  // Tracking's local map: the reference keyframe's best covisible neighbours (ORB-SLAM2: 10
  // per keyframe, up to 80 in all) plus their neighbours.
  int local_map_keyframes = 20;  // (ours) at most this many keyframes
  // Culling of new points (ORB-SLAM2's MapPointCulling): a point created cull_after_keyframes
  // keyframes ago and seen by fewer than min_observations keyframes is removed, and so is one
  // matched in fewer than min_found_ratio of the frames whose view contained it.
  int cull_after_keyframes = 2;  // (ORB-SLAM2)
  int min_observations = 2;      // (ours) ORB-SLAM2 counts an observation with depth twice and
                                 // keeps nObs > 3: two keyframes, one with depth
  double min_found_ratio = 0.25;     // (ORB-SLAM2)
  // Duplicate fusion (ORB-SLAM2's SearchInNeighbors / Fuse): points projected into the
  // neighbours within fuse_radius x level scale, Hamming at most fuse_max_distance.
  bool fuse_duplicates = true;
  int fuse_neighbours = 10;        // (ORB-SLAM2) best covisible keyframes
  double fuse_radius = 3;          // (ORB-SLAM2) pixels at level 0
  int fuse_max_distance = 50;      // (ORB-SLAM2) TH_LOW
  // (ORB-SLAM2) Projection gates: distance within [0.8 min, 1.2 max] of the scale-valid
  // range, viewing angle within acos(min_view_cos) of the mean direction.
  double min_view_cos = 0.5;
};

}  // namespace slamkit
