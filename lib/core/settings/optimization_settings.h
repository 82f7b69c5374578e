#pragma once
// Bundle adjustment settings (docs/method.md#local-mapping-and-bundle-adjustment and
// docs/method.md#global-bundle-adjustment). Each default is tagged with its source: (paper),
// (ORB-SLAM2) where the paper is silent, or (slamkit) (docs/method.md#sources).

namespace slamkit {

// The residuals every bundle adjustment shares: reprojection (u, v) plus, with depth, the
// virtual-stereo disparity bf / z (ORB-SLAM2's RGB-D u_right term), each divided by the
// keypoint's scale sigma = scale_factor^octave.
struct BaResidualSettings {
  bool use_depth = true;  // (slamkit) the depth residual; false = reprojection only (paper)
  // (slamkit) Virtual baseline x fx (pixels x metres). A depth error dz moves the disparity by
  // bf dz / z^2, so with the keypoint's sigma on it the disparity residual weighs depth as if
  // sigma_z = z^2 / bf. ORB-SLAM2's 40 (its TUM "Camera.bf") means 2.5 cm at 1 m, 15 times
  // the Kinect's noise (about 1.4 mm z^2, Khoshelham and Elberink 2012); 700 is that noise.
  double virtual_bf = 700;
  double chi2_2d = 5.991;  // (ORB-SLAM2) 95% chi-square, 2 dof: outlier test and Huber delta^2
  double chi2_3d = 7.815;  // (ORB-SLAM2) 95% chi-square, 3 dof
};

// Local BA at each new keyframe: the keyframe and its covisible neighbours move, keyframes
// that see the same points but are not neighbours stay fixed.
struct LocalBaSettings {
  bool enabled = true;         // (paper)
  int robust_iterations = 5;   // (ORB-SLAM2) LM iterations with the Huber kernel (paper: Huber)
  int refine_iterations = 10;  // (ORB-SLAM2) after removing outliers, without the kernel
  // (paper) Landmarks come from depth: after this many iterations they are held fixed and only
  // the poses move; -1 = never fixed (ORB-SLAM2).
  int fix_points_after_iterations = 2;
  // (paper) Quasi-static skip: s_e = sum |t_i|^2 + w_e sum |angles_i|^2 over the consecutive
  // frames since the last keyframe; optimise only when s_e >= min_motion.
  double motion_rotation_weight = 15;  // (paper) w_e
  double min_motion = 1e-4;            // (paper)
  // (slamkit) The best covisible neighbours that move with the keyframe; 0 = all of them, as
  // ORB-SLAM2, which keeps the window small by culling redundant keyframes (we keep every
  // keyframe: in a room the window then grows to most of the map). 5 cost 11 % less CPU on
  // desk 600 than 10, every preset's mean ATE within its seeds' scatter
  // (docs/measurement-log/experiments.md, 2026-12-05).
  int max_covisible_keyframes = 5;
  // (slamkit) Of the other keyframes observing the window's points (held fixed), those sharing
  // the most points with it; 0 = all (ORB-SLAM2). In a room most of the map sees the window's
  // points. 15 doubled the kinect lowtexture preset's error on one seed.
  int max_fixed_keyframes = 20;
  // (slamkit) Local BA at every n-th keyframe only (1 = each, as the paper); each window spans
  // the best covisible keyframes, so skipping one in n leaves no keyframe unadjusted.
  int every_keyframes = 1;
};

// Global BA after tracking: every keyframe and point, the first keyframe fixed.
struct GlobalBaSettings {
  bool enabled = true;  // (slamkit) the map's final refinement (docs/method.md#architecture)
  // (slamkit) LM iterations; ORB-SLAM2 runs 10 after a loop. After local BA the map is near its
  // optimum: 5 + 5 gave the ATE of 10 + 10 in less time.
  int iterations = 5;
  // (slamkit) Huber kernel and an outlier pass as in local BA; false = ORB-SLAM2's plain
  // least squares over every observation.
  bool robust = true;
  int refine_iterations = 5;  // (slamkit) after removing outliers (robust only)
  // (paper) Landmarks come from depth: as in local BA, the points are held fixed after this
  // many iterations, counted over both stages, and each keyframe is then solved alone; -1 =
  // never (ORB-SLAM2, whose global BA moves every point throughout).
  int fix_points_after_iterations = 2;
};

struct OptimizationSettings {
  // (slamkit) A keyframe observing fewer map points than this does not move in BA: on a plain
  // wall (tracked by dense alignment, with few points a keyframe) global BA swung such
  // keyframes by centimetres. Global BA carries them with their spanning-tree parent's
  // correction instead (ORB-SLAM2's rule for keyframes outside its global BA); local BA holds
  // them fixed.
  int min_keyframe_points = 100;
  // (slamkit) After the back end, each frame that is not a keyframe solves its pose again by
  // motion-only BA (tracking.motion_ba) on its tracking inliers, against the points as global BA
  // left them (docs/method.md#frame-refinement). Off: frames keep their tracked pose relative
  // to their reference keyframe, as ORB-SLAM2 writes them.
  bool refine_frames = true;
  BaResidualSettings residual;
  LocalBaSettings local_ba;
  GlobalBaSettings global_ba;
};

}  // namespace slamkit
