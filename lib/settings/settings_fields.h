#pragma once
// The one list of every settings field with its YAML name, walked by the reader, the writer
// and the reference (a visitor), so that adding a setting is one line here.
// A visitor provides: field(name, value&, range, note) for numbers, field(name, value&, note)
// for booleans, enums and seeds (every value valid), and section(name, settings&, about) for
// nested structs. The note gives the default's source and why (setting_note.h); `about` says
// what a section holds in a few words.
#include <cmath>
#include <limits>
#include <string>

#include "core/enum_names.h"
#include "core/number_format.h"
#include "core/settings/settings.h"
#include "settings/setting_note.h"
#include "io/value_range.h"

namespace slamkit {

template <class V>
void visit_fields(OrbSettings& s, V& v) {
  v.field("num_features", s.num_features, {1, 100000},
          from_orb_slam2("M, corners kept per frame over all levels (its TUM settings' 1000)"));
  v.field("pyramid_levels", s.pyramid_levels, {1, 12}, from_paper("levels of the image pyramid"));
  v.field("scale_factor", s.scale_factor, above(1, 2),
          from_paper("level l is the image scaled by 1/scale_factor^l"));
  v.field("fast_type", s.fast_type,
          from_slamkit(
              "FAST-9: OpenCV has no FAST-12, and FAST-12 was less repeatable; fast12 = paper"));
  v.field("fast_threshold", s.fast_threshold, {1, 255},
          from_orb_slam2("FAST intensity threshold (ORB-SLAM2's iniThFAST)"));
  v.field("fast_min_threshold", s.fast_min_threshold, {1, 255},
          from_orb_slam2("retried in grid cells where the first finds nothing (minThFAST)"));
  v.field("spread_over_image", s.spread_over_image,
          from_slamkit("a grid per level spreads the corners; false = best M by response (paper)"));
  v.field(
      "cell_size", s.cell_size, {1, 10000},
      from_orb_slam2("grid cell in level pixels, for the retry and the spreading (ORB-SLAM2's W)"));
  v.field(
      "max_cell_share", s.max_cell_share, above(0),
      from_slamkit("no cell keeps more than this times its fair share; lower costs repeatability"));
  v.field("shi_tomasi_block_size", s.shi_tomasi_block_size, {1, 99},
          from_slamkit("structure tensor window, as cv::ORB's Harris block"));
  v.field("edge_threshold", s.edge_threshold, {0, 1000},
          from_orb_slam2("border without corners: the rotated BRIEF pattern reaches 19 px"));
}

template <class V>
void visit_fields(MatcherSettings& s, V& v) {
  v.field("backend", s.backend,
          from_paper("approximate nearest neighbours by FLANN's LSH index; brute_force is exact"));
  v.field("lsh_table_number", s.lsh_table_number, {1, 100},
          from_slamkit("LSH hash tables (OpenCV's documented example values)"));
  v.field("lsh_key_size", s.lsh_key_size, {1, 32}, from_slamkit("bits per LSH hash key"));
  v.field("lsh_multi_probe_level", s.lsh_multi_probe_level, {0, 10},
          from_slamkit("neighbouring LSH buckets probed"));
  v.field("lsh_seed", s.lsh_seed,
          from_slamkit("seeds the bit choice of the LSH tables: results repeat"));
  v.field("ratio", s.ratio, above(0, 1),
          from_slamkit("Lowe's ratio test, best/second best; 1 = off"));
  v.field("mutual_check", s.mutual_check,
          from_slamkit("keep a match only if it is the best both ways"));
  v.field("max_distance", s.max_distance, {0, 256},
          from_orb_slam2("Hamming bits at most (ORB-SLAM2's TH_LOW)"));
  v.field("projection_radius", s.projection_radius, above(0),
          from_orb_slam2("search radius in level-0 pixels times the level scale (RGB-D th = 15)"));
  v.field("projection_max_distance", s.projection_max_distance, {0, 256},
          from_orb_slam2("Hamming bits at most for projected points (ORB-SLAM2's TH_HIGH)"));
  v.field("projection_ratio", s.projection_ratio, above(0, 1),
          from_orb_slam2("best/second best for projected points (ORB-SLAM2's nnratio)"));
  v.field("projection_octave_window", s.projection_octave_window, {0, 12},
          from_slamkit("keypoint level within +-this of the point's level"));
  v.field("grid_cell_size", s.grid_cell_size, above(0),
          from_orb_slam2("keypoint grid cell in pixels (ORB-SLAM2: 640/64)"));
}

template <class V>
void visit_fields(RansacSettings& s, V& v) {
  v.field("threshold_base", s.threshold_base, at_least(0),
          from_slamkit("inlier threshold's constant: keypoint localisation, depth quantisation"));
  v.field("threshold_quadratic", s.threshold_quadratic, at_least(0),
          from_slamkit("inlier threshold's z^2 term: 3 sigma of the Kinect's noise on a pair"));
  v.field("max_iterations", s.max_iterations, at_least(1),
          from_slamkit("upper bound for the adaptive iteration count"));
  v.field("confidence", s.confidence, {0, 1},
          from_slamkit("adaptive stopping: probability of one all-inlier sample"));
  v.field("min_sample_spread", s.min_sample_spread, at_least(0),
          from_slamkit("a sample with two points closer than this (metres) is rejected"));
  v.field("min_sample_shape", s.min_sample_shape, {0, 1},
          from_slamkit("a nearly collinear sample (2 area / longest edge^2 below) is rejected"));
  v.field("seed", s.seed, from_slamkit("std::mt19937 seed: same input, same result"));
}

template <class V>
void visit_fields(PointToPlaneSettings& s, V& v) {
  v.field("pyramid_levels", s.pyramid_levels, {1, 8},
          from_paper("level l is the depth image halved l times"));
  v.field("iterations_per_level", s.iterations_per_level, {1, 1000},
          from_paper("Gauss-Newton iterations on each level"));
  v.field(
      "max_pair_distance", s.max_pair_distance, above(0),
      from_slamkit("pairs farther apart (metres) are rejected; a guess a few degrees off at 3 m"));
  v.field("max_normal_angle_deg", s.max_normal_angle_deg, {0, 180},
          from_slamkit("pairs whose normals differ by more (degrees) are rejected"));
  v.field("max_neighbour_depth_ratio", s.max_neighbour_depth_ratio, {0, 1},
          from_slamkit("neighbours differing by more than this share of z: a depth edge"));
  v.field("central_difference_normals", s.central_difference_normals,
          from_slamkit("the paper's forward differences bias the rotation; false = paper"));
  v.field("convergence_rotation", s.convergence_rotation, at_least(0),
          from_slamkit("converged when the last increment rotates less (radians)"));
  v.field("convergence_translation", s.convergence_translation, at_least(0),
          from_slamkit("converged when the last increment moves less (metres)"));
  v.field("min_correspondences", s.min_correspondences, at_least(1),
          from_slamkit("fewer pairs on any level: failure"));
  v.field("min_eigenvalue", s.min_eigenvalue, {0, 1},
          from_slamkit("conditioning: one plane scores ~0, a room corner ~0.01-0.1"));
  v.field("normal_smoothing_diameter", s.normal_smoothing_diameter, {0, 100},
          from_slamkit("bilateral filter of the depth for normals (KinectFusion); 0 = paper"));
  v.field("normal_smoothing_sigma_depth", s.normal_smoothing_sigma_depth, above(0),
          from_slamkit("that filter's depth sigma (metres)"));
  v.field("photometric_weight", s.photometric_weight, at_least(0),
          from_slamkit("grey-level residuals on edges hold plain walls; 0 = the paper's geometry"));
  v.field("photometric_huber", s.photometric_huber, above(0),
          from_slamkit("Huber kernel of the photometric residual (grey levels)"));
  v.field("photometric_min_gradient", s.photometric_min_gradient, at_least(0),
          from_slamkit("grey levels a pixel that make an edge pixel"));
}

template <class V>
void visit_fields(MotionBaSettings& s, V& v) {
  v.field("rounds", s.rounds, {0, 100},
          from_orb_slam2("optimisation rounds, outliers re-classified after each"));
  v.field("iterations_per_round", s.iterations_per_round, {0, 1000},
          from_orb_slam2("Levenberg-Marquardt iterations per round"));
  v.field("robust_rounds", s.robust_rounds, {0, 100},
          from_orb_slam2("rounds using the Huber kernel; later ones none"));
  v.field("chi2_2d", s.chi2_2d, above(0), from_orb_slam2("95% chi-square, 2 dof (pixels^2)"));
  v.field("chi2_3d", s.chi2_3d, above(0), from_orb_slam2("95% chi-square, 3 dof"));
  v.field("use_depth", s.use_depth,
          from_slamkit("a residual on the virtual-stereo disparity bf/z, RGB-D's u_right"));
  v.field("virtual_bf", s.virtual_bf, above(0),
          from_orb_slam2("\"Camera.bf\" of ORB-SLAM2's TUM settings: fx * 7.7 cm"));
  v.field("min_inliers", s.min_inliers, at_least(0),
          from_orb_slam2("fewer inliers: the refinement has failed"));
  v.field("min_matches_after_dense", s.min_matches_after_dense, at_least(0),
          from_slamkit("fewer matches after dense alignment: its pose stands unrefined"));
}

template <class V>
void visit_fields(FailureSettings& s, V& v) {
  v.field("max_speed", s.max_speed, above(0),
          from_slamkit("faster between frames (m/s) is a failure, not motion"));
  v.field("max_angular_speed_deg", s.max_angular_speed_deg, above(0),
          from_slamkit("faster turning (deg/s) is a failure, not motion"));
  v.field("min_dt", s.min_dt, above(0),
          from_slamkit("shorter gaps (s) count as this long: no blow-up on dt ~ 0"));
  v.field("min_inliers", s.min_inliers, at_least(0),
          from_orb_slam2("fewer inlier matches: failure"));
  v.field("trusted_inliers", s.trusted_inliers, at_least(0),
          from_slamkit("a pose with this many BA inliers skips the speed limits; 0 = never"));
  v.field("trusted_inlier_ratio", s.trusted_inlier_ratio, {0, 1},
          from_slamkit("... when they are at least this share of the frame's matches"));
}

template <class V>
void visit_fields(TrackingSettings& s, V& v) {
  v.field("min_pairs_for_svd", s.min_pairs_for_svd, at_least(3),
          from_paper("fewer valid 3D pairs: dense point-to-plane alignment instead"));
  v.field("lost_search_radius_factor", s.lost_search_radius_factor, {1, 100},
          from_slamkit("widens the projection search after a lost frame, as ORB-SLAM2"));
  v.field("min_matches_for_box", s.min_matches_for_box, at_least(0),
          from_slamkit("matched points that bound dense alignment's co-visible box"));
  v.field("relocalisation_candidates", s.relocalisation_candidates, at_least(0),
          from_slamkit("keyframes most alike by window code tried after a lost frame"));
  v.field("relocalisation_min_inliers", s.relocalisation_min_inliers, at_least(3),
          from_orb_slam2("inliers whose pose seeds a projection search after a lost frame"));
  v.field("unroll_exposure", s.unroll_exposure,
          from_slamkit("keypoints moved to the colour stamp: rolling shutter, depth stamps"));
  v.section("ransac", s.ransac, "closed-form SVD alignment of 3D-3D pairs inside RANSAC");
  v.section("point_to_plane", s.point_to_plane,
            "dense point-to-plane alignment, the paper's fallback with too few pairs");
  v.section("motion_ba", s.motion_ba,
            "motion-only BA of the current pose (ORB-SLAM2's PoseOptimization)");
  v.section("failure", s.failure, "plausibility of a tracked pose");
}

template <class V>
void visit_fields(KeyframeSettings& s, V& v) {
  v.field("similarity_threshold", s.similarity_threshold, {0, 1},
          from_paper("zeta below this makes a keyframe"));
  v.field("pyramid_levels", s.pyramid_levels, {1, 12},
          from_paper("levels encoded, as the feature pyramid"));
  v.field("scale_factor", s.scale_factor, above(1, 2),
          from_paper("scale between encoded levels, as the feature pyramid"));
  v.field("pattern_seed", s.pattern_seed,
          from_slamkit("fixes the random pixel of every 2x2 window for a run"));
  v.field("neighbour_frames", s.neighbour_frames, {0, 100},
          from_slamkit("frames on each side of the latest keyframe also compared"));
  v.field("min_tracked_ratio", s.min_tracked_ratio, {0, 1},
          from_slamkit("tracking less than this share of the keyframe's matches makes one"));
}

template <class V>
void visit_fields(MappingSettings& s, V& v) {
  v.field("covisibility_min_shared", s.covisibility_min_shared, at_least(1),
          from_orb_slam2("keyframes sharing this many points are linked"));
  v.field("local_map_keyframes", s.local_map_keyframes, at_least(1),
          from_slamkit("tracking's local map holds at most this many keyframes"));
  v.field("cull_after_keyframes", s.cull_after_keyframes, at_least(0),
          from_orb_slam2("a new point is judged this many keyframes after its creation"));
  v.field("min_observations", s.min_observations, at_least(1),
          from_slamkit("fewer observing keyframes by then: removed (ORB-SLAM2's nObs > 3)"));
  v.field("min_found_ratio", s.min_found_ratio, {0, 1},
          from_orb_slam2("matched in fewer of the frames whose view held it: removed"));
  v.field(
      "fuse_duplicates", s.fuse_duplicates,
      from_orb_slam2("fuse duplicate points in the neighbours (ORB-SLAM2's SearchInNeighbors)"));
  v.field("fuse_neighbours", s.fuse_neighbours, at_least(0),
          from_orb_slam2("best covisible keyframes searched for duplicates"));
  v.field("fuse_radius", s.fuse_radius, at_least(0),
          from_orb_slam2("duplicate search radius, pixels at level 0 times the level scale"));
  v.field("fuse_max_distance", s.fuse_max_distance, {0, 256},
          from_orb_slam2("Hamming bits at most for a duplicate (TH_LOW)"));
  v.field("min_view_cos", s.min_view_cos, {-1, 1},
          from_orb_slam2("viewing angle within acos(this) of the point's mean direction"));
  v.field("cull_keyframes", s.cull_keyframes,
          from_slamkit("redundant keyframe culling, as ORB-SLAM2: off, it moved ATE both ways"));
  v.field("culling_redundancy", s.culling_redundancy, {0, 1},
          from_orb_slam2("culled when more than this share of its close points is redundant"));
  v.field("culling_observers", s.culling_observers, {1, 1000},
          from_orb_slam2("keyframes at the same octave or finer that make a point redundant"));
  v.field("culling_max_depth", s.culling_max_depth, {0, 1000},
          from_orb_slam2("close points only, metres (ThDepth: 40 TUM baselines)"));
}

template <class V>
void visit_fields(BaResidualSettings& s, V& v) {
  v.field("use_depth", s.use_depth,
          from_slamkit("the depth residual; false = reprojection only (paper)"));
  v.field("virtual_bf", s.virtual_bf, above(0),
          from_slamkit(
              "virtual baseline x fx that weighs depth as the Kinect's noise (ORB-SLAM2: 40)"));
  v.field("chi2_2d", s.chi2_2d, above(0),
          from_orb_slam2("95% chi-square, 2 dof: outlier test and Huber delta^2"));
  v.field("chi2_3d", s.chi2_3d, above(0), from_orb_slam2("95% chi-square, 3 dof"));
}

template <class V>
void visit_fields(LocalBaSettings& s, V& v) {
  v.field("enabled", s.enabled, from_paper("local BA at each new keyframe"));
  v.field("robust_iterations", s.robust_iterations, at_least(0),
          from_orb_slam2("LM iterations with the Huber kernel (paper: Huber)"));
  v.field("refine_iterations", s.refine_iterations, at_least(0),
          from_orb_slam2("LM iterations after removing outliers, without the kernel"));
  v.field("fix_points_after_iterations", s.fix_points_after_iterations, at_least(-1),
          from_paper("landmarks come from depth: fixed after this many; -1 = never"));
  v.field("motion_rotation_weight", s.motion_rotation_weight, at_least(0),
          from_paper("w_e, the rotation's weight in the quasi-static motion s_e"));
  v.field("min_motion", s.min_motion, at_least(0),
          from_paper("optimise only when s_e since the last keyframe reaches this"));
  v.field("max_covisible_keyframes", s.max_covisible_keyframes, at_least(0),
          from_slamkit("best covisible neighbours that move; 0 = all (ORB-SLAM2)"));
  v.field("max_fixed_keyframes", s.max_fixed_keyframes, at_least(0),
          from_slamkit("fixed keyframes sharing most points with the window; 0 = all"));
  v.field("every_keyframes", s.every_keyframes, at_least(1),
          from_slamkit("local BA at every n-th keyframe only; 1 = each (paper)"));
}

template <class V>
void visit_fields(GlobalBaSettings& s, V& v) {
  v.field("enabled", s.enabled,
          from_slamkit("global BA over every keyframe and point after tracking"));
  v.field(
      "iterations", s.iterations, at_least(0),
      from_slamkit("LM iterations: after local BA the map is near its optimum (ORB-SLAM2: 10)"));
  v.field(
      "robust", s.robust,
      from_slamkit("Huber kernel and an outlier pass; false = plain least squares (ORB-SLAM2)"));
  v.field("refine_iterations", s.refine_iterations, at_least(0),
          from_slamkit("LM iterations after removing outliers (robust only)"));
  v.field("fix_points_after_iterations", s.fix_points_after_iterations, at_least(-1),
          from_paper("points fixed after this many, each keyframe then alone; -1 = never"));
}

template <class V>
void visit_fields(OptimizationSettings& s, V& v) {
  v.field("min_keyframe_points", s.min_keyframe_points, at_least(0),
          from_slamkit("a keyframe observing fewer map points does not move in BA"));
  v.field("refine_frames", s.refine_frames,
          from_slamkit("frames solved again against the final map; false = as tracked "
                       "relative to their keyframe (ORB-SLAM2)"));
  v.section("residual", s.residual, "the residuals every bundle adjustment shares");
  v.section("local_ba", s.local_ba, "local BA at each new keyframe");
  v.section("global_ba", s.global_ba, "global BA after tracking");
}

template <class V>
void visit_fields(LoopSettings& s, V& v) {
  v.field("enabled", s.enabled, from_slamkit("the loop pass between tracking and global BA"));
  v.field("train_on_sequence", s.train_on_sequence,
          from_slamkit("offline the sequence is known: train the vocabulary on its keyframes"));
  v.field("training_keyframe_step", s.training_keyframe_step, at_least(1),
          from_slamkit("training takes every n-th keyframe's descriptors"));
  v.field("recent_keyframes", s.recent_keyframes, at_least(0),
          from_orb_slam2(
              "keyframes this close in index are no candidates, nor loops before this many"));
  v.field("min_consistent_neighbours", s.min_consistent_neighbours, at_least(0),
          from_paper("a candidate stands with this many candidate neighbours"));
  v.field("consistency_neighbours", s.consistency_neighbours, at_least(1),
          from_orb_slam2("best covisible keyframes of a candidate checked for consistency"));
  v.field("max_verified", s.max_verified, at_least(1),
          from_slamkit("candidates verified per keyframe, best score first"));
  v.field("min_matches", s.min_matches, at_least(3), from_paper("fewer ORB matches: no loop"));
  v.field("min_inliers", s.min_inliers, at_least(3),
          from_orb_slam2("RANSAC inliers of the relative pose at least"));
  v.field("neighbourhood_radius", s.neighbourhood_radius, above(0),
          from_orb_slam2("search radius projecting the candidate's neighbourhood, level-0 px"));
  v.field("neighbourhood_max_distance", s.neighbourhood_max_distance, at_least(0),
          from_orb_slam2("Hamming bits at most for those matches"));
  v.field("min_neighbourhood_inliers", s.min_neighbourhood_inliers, at_least(0),
          from_orb_slam2("inliers of the pose refined on the neighbourhood at least"));
  v.field("max_pose_error", s.max_pose_error, above(0), from_paper("kappa, metres"));
  v.field(
      "min_correction", s.min_correction, at_least(0),
      from_orb_slam2("correct the map only when a loop moves it this much (metres); 0 = always"));
  v.field("essential_min_weight", s.essential_min_weight, at_least(1),
          from_orb_slam2("essential graph: covisibility edges of this many shared points"));
  v.field("correction_iterations", s.correction_iterations, at_least(1),
          from_orb_slam2("LM iterations of the essential graph optimisation"));
  v.field("fuse_points", s.fuse_points,
          from_orb_slam2("fuse the points around the loop into its keyframes (SearchAndFuse)"));
  v.field("fuse_radius", s.fuse_radius, above(0),
          from_orb_slam2("that fusion's search radius, pixels at level 0"));
}

template <class V>
void visit_fields(FusionSettings& s, V& v) {
  v.field("enabled", s.enabled, from_slamkit("fuse the map after the run"));
  v.field("method", s.method,
          from_slamkit("tsdf: the zero-crossing surface of a TSDF (as Open3D's); centroids: "
                       "each voxel's mean point"));
  v.field("frame_step", s.frame_step, at_least(0),
          from_slamkit("frames back-projected: 0 = the keyframes, n > 0 = every n-th frame"));
  v.field("pixel_stride", s.pixel_stride, at_least(1), from_slamkit("every n-th pixel in u and v"));
  v.field("keyframe_cache_mb", s.keyframe_cache_mb, at_least(0),
          from_slamkit("keyframe samples kept from tracking for fusion (MB); 0 = load all"));
  v.field("max_depth", s.max_depth, above(0),
          from_slamkit("metres: Kinect noise grows with z^2 (4 mm at 1.5 m)"));
  v.field("voxel_size", s.voxel_size, above(0), from_slamkit("metres, the voxel grid's leaf"));
  v.field("batch_frames", s.batch_frames, at_least(1),
          from_slamkit("frames loaded in parallel at a time (bounds memory)"));
  v.field("truncation", s.truncation, above(0),
          from_slamkit("tsdf: metres, the signed distance's cut (Open3D's examples' 4 cm)"));
  v.field("noise_weighting", s.noise_weighting,
          from_slamkit("tsdf: weigh each depth by 1/sigma^2 of the Kinect noise model"));
  v.field("edge_jump", s.edge_jump, at_least(0),
          from_slamkit("tsdf: leave out depth with a neighbour this share nearer or farther"));
  v.field("smoothing_radius", s.smoothing_radius, {0, 10},
          from_slamkit("tsdf: depth replaced by a plane fitted within this many samples; 0 = raw"));
  v.field("min_weight", s.min_weight, at_least(0),
          from_slamkit("tsdf: surface kept where it weighs this many head-on views at 1 m"));
  v.field("mesh", s.mesh, from_slamkit("tsdf: also write mesh.ply (marching cubes)"));
  v.field("remove_outliers", s.remove_outliers,
          from_slamkit("centroids: leave out voxels with few occupied neighbours"));
  v.field("outlier_neighbour_share", s.outlier_neighbour_share, Range{0, 1},
          from_slamkit("a voxel with fewer occupied neighbours than this share of the median's "
                       "is left out"));
  v.field("binary_ply", s.binary_ply, from_slamkit("binary PLY; false = ASCII"));
}

template <class V>
void visit_fields(VocabularySettings& s, V& v) {
  v.field("branching", s.branching, {2, 255},
          from_slamkit("k, children per node; 10 and 5 give a generic vocabulary"));
  v.field("depth", s.depth, {1, 10},
          from_slamkit("L, levels below the root; leaves are the words"));
  v.field("iterations", s.iterations, {1, 1000},
          from_slamkit("k-medians iterations per node at most (stops earlier when stable)"));
  v.field("seed", s.seed,
          from_slamkit("seeds k-means++ at every node: the same input gives the same tree"));
  v.field("frame_step", s.frame_step, {1, 100000},
          from_slamkit("`vocab train` extracts features from every n-th frame"));
  v.field("direct_index_level", s.direct_index_level, {0, 10},
          from_orb_slam2("level whose nodes group features for guided matching, as ORB-SLAM2"));
}

template <class V>
void visit_fields(PipelineSettings& s, V& v) {
  v.field("threads", s.threads, at_least(0),
          from_slamkit("OpenMP threads for the parallel stages; 0 = all cores"));
  v.field("chunk_frames", s.chunk_frames, at_least(1),
          from_slamkit("frames prepared in parallel at a time (bounds memory)"));
  v.field("evaluate", s.evaluate,
          from_slamkit("with groundtruth, compute ATE/RPE at the end of a run"));
  v.field("lost_frames", s.lost_frames,
          from_orb_slam2("a lost frame's trajectory line: omitted, or the motion model's guess"));
}

template <class V>
void visit_fields(ReportSettings& s, V& v) {
  v.field("enabled", s.enabled, from_slamkit("`run` writes report.html (`--no-report` skips it)"));
  v.field("point_budget", s.point_budget, {0, 50'000'000},
          from_slamkit("map points in the page at most, an even subset of map.ply"));
  v.field("mesh_triangle_budget", s.mesh_triangle_budget, {0, 50'000'000},
          from_slamkit("mesh.ply's triangles in the page at most, simplified to fit; 0 = none"));
}

template <class V>
void visit_fields(Settings& s, V& v) {
  v.section("orb", s.orb, "ORB extraction");
  v.section("matcher", s.matcher, "descriptor matching");
  v.section("tracking", s.tracking, "the pose of each frame");
  v.section("keyframes", s.keyframes, "keyframe selection");
  v.section("mapping", s.mapping, "map upkeep at each new keyframe (ORB-SLAM2's LocalMapping)");
  v.section("optimization", s.optimization, "bundle adjustment");
  v.section("loop", s.loop, "loop closing");
  v.section("map", s.map, "the map: a TSDF's surface (points, optionally a mesh)");
  v.section("vocabulary", s.vocabulary,
            "the bag-of-words vocabulary: training of the k-ary tree, its direct index");
  v.section("pipeline", s.pipeline, "the batch engine");
  v.section("report", s.report, "the report page of a run (report.html)");
}

// Names of enum values in settings files.
inline constexpr EnumNames<FastType, 2> kFastTypeNames = {
    {{FastType::kFast9, "fast9"}, {FastType::kFast12, "fast12"}}};
inline constexpr EnumNames<MatcherBackend, 2> kMatcherBackendNames = {
    {{MatcherBackend::kFlannLsh, "flann_lsh"}, {MatcherBackend::kBruteForce, "brute_force"}}};
inline constexpr EnumNames<MapMethod, 2> kMapMethodNames = {
    {{MapMethod::kTsdf, "tsdf"}, {MapMethod::kCentroids, "centroids"}}};
inline constexpr EnumNames<LostFrames, 2> kLostFramesNames = {
    {{LostFrames::kOmit, "omit"}, {LostFrames::kMotionModel, "motion-model"}}};
inline const auto& enum_names(FastType) { return kFastTypeNames; }
inline const auto& enum_names(MapMethod) { return kMapMethodNames; }
inline const auto& enum_names(LostFrames) { return kLostFramesNames; }
inline const auto& enum_names(MatcherBackend) { return kMatcherBackendNames; }

}  // namespace slamkit
