#pragma once
// Loop closing settings (SPEC section 5; the paper's numbers where it gives them, ORB-SLAM2's
// from ORBSLAM2_BACKEND.md otherwise).

namespace slamkit {

struct LoopSettings {
  bool enabled = true;  // (design card) the loop pass between tracking and global BA
  // (beyond) Offline the whole sequence is known: the vocabulary is trained on the keyframes'
  // own descriptors (vocabulary settings: k, L) unless a vocabulary file is given
  // (`run --vocabulary FILE`).
  bool train_on_sequence = true;
  // (ours) That training takes the descriptors of every n-th active keyframe; the others are
  // still looked up in the tree. 2 halves the training (loop 600: 2.4 -> 1.2 s) and moved ATE
  // by -0.15 to +0.07 mm (loop 600 seeds 1-3, long 2000); 4 made every loop seed 0.13 mm worse.
  int training_keyframe_step = 1;
  // (ORB-SLAM2) Keyframes this close in index to the query are never loop candidates (besides
  // its covisible neighbours), and no loop is searched before this many keyframes exist.
  int recent_keyframes = 10;
  // (paper) A candidate stands only when at least this many of its covisible neighbours are
  // candidates too (consistency), among its best `consistency_neighbours`.
  int min_consistent_neighbours = 5;
  int consistency_neighbours = 10;  // (ORB-SLAM2) its best covisible keyframes
  int max_verified = 3;             // (ours) candidates verified per keyframe, best score first
  int min_matches = 50;             // (paper) fewer ORB matches: no loop
  int min_inliers = 20;             // (ORB-SLAM2) RANSAC inliers of the relative pose
  // (ORB-SLAM2) With the measured pose, the points around the candidate (its own and its
  // covisible neighbours') are projected into the keyframe (radius in pixels at level 0,
  // Hamming at most neighbourhood_max_distance) and the pose refined on every match: a loop
  // needs at least this many inliers in all.
  double neighbourhood_radius = 10;
  int neighbourhood_max_distance = 50;
  int min_neighbourhood_inliers = 40;
  double max_pose_error = 1.0;  // (paper) kappa, metres
  // The map is corrected only when some accepted loop's measured pose differs from the map's
  // by at least this (metres; ORB-SLAM2 always corrects: 0). 2 cm had helped before dense
  // alignment weighed grey levels (lowtexture 400: ATE 1.86 -> 2.12 mm when correcting 3-14 mm
  // gaps); with them, correcting every gap is as good or better on every preset (loop 600
  // seed 2 6.38 -> 5.73 mm, lowtexture 600 seed 3 5.88 -> 2.37 mm, lowtexture 400 seed 1 3.26 ->
  // 1.62 mm, lookalike 4.98 -> 2.12 mm).
  double min_correction = 0;
  // (ORB-SLAM2) Essential graph: covisibility edges of at least this many shared points, and
  // the LM iterations of its optimisation.
  int essential_min_weight = 100;
  int correction_iterations = 20;
  // (ORB-SLAM2's SearchAndFuse) After the correction, the points seen around the loop keyframe
  // are fused into the keyframe that found it and its covisible neighbours, so that the global
  // BA sees both ends of the loop observe the same points; search radius in pixels at level 0.
  bool fuse_points = true;
  double fuse_radius = 4;
};

}  // namespace slamkit
