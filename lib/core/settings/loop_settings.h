#pragma once
// Loop closing settings (docs/method.md#loop-closing): the paper's numbers where it gives them,
// ORB-SLAM2's otherwise. Each default is tagged with its source: (paper), (ORB-SLAM2) or
// (slamkit) (docs/method.md#sources).

namespace slamkit {

struct LoopSettings {
  // (slamkit) The loop pass between tracking and global BA (docs/method.md#architecture).
  bool enabled = true;
  // (slamkit) Offline the whole sequence is known: the vocabulary is trained on the keyframes'
  // own descriptors (vocabulary settings: k, L) unless a vocabulary file is given
  // (`run --vocabulary FILE`).
  bool train_on_sequence = true;
  // (slamkit) That training takes the descriptors of every n-th active keyframe; the others are
  // still looked up in the tree. Larger steps train faster and cost accuracy.
  int training_keyframe_step = 1;
  // (ORB-SLAM2) Keyframes this close in index to the query are never loop candidates (besides
  // its covisible neighbours), and no loop is searched before this many keyframes exist.
  int recent_keyframes = 10;
  // (paper) A candidate stands only when at least this many of its covisible neighbours are
  // candidates too (consistency), among its best `consistency_neighbours`.
  int min_consistent_neighbours = 5;
  int consistency_neighbours = 10;  // (ORB-SLAM2) its best covisible keyframes
  int max_verified = 3;             // (slamkit) candidates verified per keyframe, best score first
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
  // (ORB-SLAM2) The map is corrected only when some accepted loop's measured pose differs from
  // the map's by at least this (metres); ORB-SLAM2 always corrects: 0. A threshold had helped
  // before dense alignment weighed grey levels; with them, correcting every gap is as good or
  // better on every preset.
  double min_correction = 0;
  // (ORB-SLAM2) Essential graph: covisibility edges of at least this many shared points, and
  // the LM iterations of its optimisation.
  int essential_min_weight = 100;
  int correction_iterations = 20;
  // (ORB-SLAM2) After the correction (its SearchAndFuse), the points seen around the loop
  // keyframe are fused into the keyframe that found it and its covisible neighbours, so that the
  // global BA sees both ends of the loop observe the same points; search radius in pixels at
  // level 0.
  bool fuse_points = true;
  double fuse_radius = 4;
};

}  // namespace slamkit
