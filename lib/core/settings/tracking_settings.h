#pragma once
// Pose solvers of the front end (docs/method.md#matching-and-pose). Each default is tagged with
// its source: (paper), (ORB-SLAM2) or (slamkit) (docs/method.md#sources).
#include <cstdint>

namespace slamkit {

// Closed-form SVD alignment of 3D-3D pairs inside RANSAC.
struct RansacSettings {
  // Inlier threshold on |q - T q'| (metres): base + quadratic * z^2, z the depth of q. The
  // quadratic term follows the Kinect's axial noise (sigma ~ 1.4 mm * z^2, Khoshelham and
  // Elberink 2012; 3 sigma of a pair gives ~6 mm * z^2), the base covers keypoint
  // localisation (1 px is ~2 mm at 1 m) and depth quantisation. 2.6 cm at 1 m, 7.4 cm at 3 m.
  double threshold_base = 0.02;        // metres (slamkit)
  double threshold_quadratic = 0.006;  // metres per metre^2 (slamkit)
  int max_iterations = 300;            // (slamkit) upper bound for the adaptive rule
  double confidence = 0.99;            // (slamkit) adaptive stopping: P(one all-inlier sample)
  // A minimal sample is rejected when two of its points are closer than this (metres) or
  // when it is nearly collinear: 2 * area / longest_edge^2 below min_sample_shape (an
  // equilateral triangle scores 0.87, a sliver 0).
  double min_sample_spread = 0.02;  // metres (slamkit)
  double min_sample_shape = 0.1;    // (slamkit)
  uint32_t seed = 42;               // (slamkit) std::mt19937 seed: same input, same result
};

// Dense point-to-plane alignment, the paper's fallback when there are too few pairs.
struct PointToPlaneSettings {
  int pyramid_levels = 2;        // (paper) level l is the depth image halved l times
  int iterations_per_level = 3;  // (paper) Gauss-Newton iterations on each level
  // Projective association: a pair is rejected when its points are farther apart than
  // this (metres) or their normals differ by more than max_normal_angle_deg.
  // 0.2 m covers a guess a few degrees off at 3 m; at 0.1 m a wall seen at a slant can
  // drop out of the first iteration and leave a direction unconstrained.
  double max_pair_distance = 0.2;    // metres (slamkit)
  double max_normal_angle_deg = 30;  // degrees (slamkit)
  // (slamkit) Neighbours whose depths differ by more than this fraction of z give no normal (a
  // depth edge, not a surface). A 80-degree grazing plane at 640 px still passes.
  double max_neighbour_depth_ratio = 0.05;
  // (slamkit) Normals from central differences (u-1..u+1, v-1..v+1) rather than the paper's
  // forward ones (u..u+1, v..v+1), which correlate a point's noise with its own normal and
  // bias the rotation; false = the paper's.
  bool central_difference_normals = true;
  // (slamkit) Converged when the last increment moves less than these.
  double convergence_rotation = 1e-3;     // radians (0.057 deg)
  double convergence_translation = 1e-3;  // metres
  // (slamkit) Fewer pairs than this on any level: failure.
  int min_correspondences = 100;
  // (slamkit) Conditioning: smallest eigenvalue of the normal matrix per pair, rotations scaled
  // by the RMS point distance (dimensionless, 0..1). A view of a single plane leaves 3
  // directions unconstrained and scores ~0; a room corner scores ~0.01-0.1.
  double min_eigenvalue = 1e-3;
  // (slamkit) Normals from depth smoothed by a bilateral filter of this diameter (pixels) and
  // depth sigma (metres), as KinectFusion does; 0 = the paper's raw neighbour differences,
  // which Kinect-like noise (~3 mm at 1.5 m over a 3 mm baseline) turns mostly random.
  int normal_smoothing_diameter = 7;
  double normal_smoothing_sigma_depth = 0.03;
  // (slamkit) Photometric residuals on the current frame's intensity edges beside the
  // point-to-plane ones, as dense RGB-D odometry combines them (Whelan et al. 2013). Walls
  // whose relief barely constrains a sideways move (the smallest eigenvalue near
  // min_eigenvalue, along the camera's x) are held by their edges. Weight of a squared grey
  // level against a squared point-to-plane metre (sigma_z / sigma_I squared, about
  // (3 mm / 3 levels)^2 = 1e-6); 0 = the paper's geometry alone.
  double photometric_weight = 1e-6;
  double photometric_huber = 10;        // (slamkit) grey levels: Huber kernel of the residual
  double photometric_min_gradient = 4;  // (slamkit) grey levels a pixel: an edge pixel
};

// Motion-only bundle adjustment of the current pose (ORB-SLAM2's PoseOptimization).
struct MotionBaSettings {
  int rounds = 4;                 // (ORB-SLAM2) optimisation rounds, outliers re-classified
  int iterations_per_round = 10;  // (ORB-SLAM2) Levenberg-Marquardt iterations per round
  int robust_rounds = 2;          // (ORB-SLAM2) rounds using the Huber kernel; later ones none
  double chi2_2d = 5.991;         // (ORB-SLAM2) 95% chi-square, 2 dof (pixels^2)
  double chi2_3d = 7.815;         // (ORB-SLAM2) 95% chi-square, 3 dof
  // RGB-D: a third residual on the virtual-stereo disparity bf/z (pixels), the RGB-D form
  // of ORB-SLAM2's u_right term. Its noise grows with z^2, as the Kinect's does.
  bool use_depth = true;   // (slamkit) default on
  double virtual_bf = 40;  // (ORB-SLAM2) "Camera.bf" of its TUM settings: fx * 7.7 cm
  int min_inliers = 10;    // (ORB-SLAM2) fewer inliers: the refinement has failed
  // (slamkit) After dense alignment the matches are few and unverified, and on plain surfaces
  // they sit on shading edges, where refining on them moves a right dense pose. With fewer
  // matches than this the dense pose stands. The paper refines at any count: set it to
  // min_inliers for that.
  int min_matches_after_dense = 50;
};

// Plausibility of a tracked pose.
struct FailureSettings {
  // (slamkit) Speeds above these between consecutive frames are a tracking failure, not
  // motion. Handheld TUM sequences stay well under them.
  double max_speed = 3.0;              // metres per second
  double max_angular_speed_deg = 200;  // degrees per second
  // (slamkit) Seconds; shorter gaps count as this long (no blow-up on dt ~ 0).
  double min_dt = 0.01;
  int min_inliers = 10;  // (ORB-SLAM2) fewer inlier matches: failure
  // (slamkit) A pose the features vouch for is motion, however fast: refined by the motion-only
  // BA with at least this many inliers, which are at least this share of the frame's matches,
  // it skips the speed limits (ORB-SLAM2 has none), so that a real whip is not replaced by the
  // motion model's guess. 0 inliers = the speed limits alone decide.
  int trusted_inliers = 100;
  double trusted_inlier_ratio = 0.7;
};

struct TrackingSettings {
  int min_pairs_for_svd = 50;  // (paper) fewer valid 3D pairs: dense point-to-plane instead
  // (slamkit) After a lost frame the predicted pose is poor: the projection search radius is
  // multiplied by this (ORB-SLAM2 widens its window likewise).
  double lost_search_radius_factor = 4;
  // (slamkit) Dense alignment's co-visible box comes from the matched points when there are at
  // least this many; with fewer the whole image is used.
  int min_matches_for_box = 30;
  // (slamkit) After a lost frame, the frame is matched by descriptor against the latest
  // keyframe and this many others most similar by window code (the paper's encoding used
  // for place recognition), and the best is taken: no pose prior is needed.
  int relocalisation_candidates = 3;
  // (ORB-SLAM2) Inliers of those descriptor matches that seed a projection search of the
  // map from their pose, when they are too few to be judged on (ORB-SLAM2's Relocalization
  // solves PnP from 15 matches).
  int relocalisation_min_inliers = 15;
  // (slamkit) Keypoints are moved to the colour stamp along the camera's velocity: the rolling
  // shutter's skew undone (the calibration's readout_time) and depth read at its own stamp.
  bool unroll_exposure = true;
  RansacSettings ransac;
  PointToPlaneSettings point_to_plane;
  MotionBaSettings motion_ba;
  FailureSettings failure;
};

}  // namespace slamkit
