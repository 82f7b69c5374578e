#pragma once
// Map upkeep at each new keyframe, as ORB-SLAM2's LocalMapping
// (docs/method.md#local-mapping-and-bundle-adjustment). Each default is tagged with its source:
// (paper), (ORB-SLAM2) or (slamkit) (docs/method.md#sources).

namespace slamkit {

struct MappingSettings {
  int covisibility_min_shared = 15;  // (ORB-SLAM2) keyframes sharing this many points are linked
  // Tracking's local map: the reference keyframe's best covisible neighbours (ORB-SLAM2: 10
  // per keyframe, up to 80 in all) plus their neighbours.
  int local_map_keyframes = 20;  // (slamkit) at most this many keyframes
  // Culling of new points (ORB-SLAM2's MapPointCulling): a point created cull_after_keyframes
  // keyframes ago and seen by fewer than min_observations keyframes is removed, and so is one
  // matched in fewer than min_found_ratio of the frames whose view contained it.
  int cull_after_keyframes = 2;   // (ORB-SLAM2)
  int min_observations = 2;       // (slamkit) ORB-SLAM2 counts an observation with depth twice
                                  // and keeps nObs > 3: two keyframes, one with depth
  double min_found_ratio = 0.25;  // (ORB-SLAM2)
  // (ORB-SLAM2) Duplicate fusion (its SearchInNeighbors / Fuse): points projected into the
  // neighbours within fuse_radius x level scale, Hamming at most fuse_max_distance.
  bool fuse_duplicates = true;
  int fuse_neighbours = 10;    // (ORB-SLAM2) best covisible keyframes
  double fuse_radius = 3;      // (ORB-SLAM2) pixels at level 0
  int fuse_max_distance = 50;  // (ORB-SLAM2) TH_LOW
  // (ORB-SLAM2) Projection gates: distance within [0.8 min, 1.2 max] of the scale-valid
  // range, viewing angle within acos(min_view_cos) of the mean direction.
  double min_view_cos = 0.5;
  // Keyframe culling (ORB-SLAM2's KeyFrameCulling), after each local BA over the keyframe's
  // covisible neighbours: one whose close points (keypoint depth up to culling_max_depth) are
  // redundant in more than culling_redundancy of cases is culled; a point is redundant when
  // culling_observers other keyframes see it at the same octave or one finer. ORB-SLAM2 culls;
  // (slamkit) off by default: it saves time, but moved ATE both ways, by seed and sequence.
  bool cull_keyframes = false;
  double culling_redundancy = 0.9;  // (ORB-SLAM2)
  int culling_observers = 3;        // (ORB-SLAM2)
  // (ORB-SLAM2) ThDepth: 40 times its TUM baseline, 40 / fx = 0.077 m
  double culling_max_depth = 3.1;
};

}  // namespace slamkit
