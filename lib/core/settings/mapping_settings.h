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
  int cull_after_keyframes = 2;   // (ORB-SLAM2)
  int min_observations = 2;       // (ours) ORB-SLAM2 counts an observation with depth twice and
                                  // keeps nObs > 3: two keyframes, one with depth
  double min_found_ratio = 0.25;  // (ORB-SLAM2)
  // Duplicate fusion (ORB-SLAM2's SearchInNeighbors / Fuse): points projected into the
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
  // (ours) off by default: `run` takes 10-38% less time with it (it culls a quarter of desk
  // 600's keyframes, nearly half of loop 600's), but ATE moves with it by up to 6 mm a seed on loop
  // 600, both ways, and the mean over seeds 1-6 of loop 600 got worse (16.1 -> 17.9 mm) while
  // lowtexture 600's got better (3.9 -> 3.8 mm); README's back-end section has the table.
  bool cull_keyframes = false;
  double culling_redundancy = 0.9;  // (ORB-SLAM2)
  int culling_observers = 3;        // (ORB-SLAM2)
  // (ORB-SLAM2) ThDepth: 40 times its TUM baseline, 40 / fx = 0.077 m
  double culling_max_depth = 3.1;
};

}  // namespace slamkit
