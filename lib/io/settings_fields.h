#pragma once
// The one list of every settings field with its YAML name, walked by the reader and the
// writer alike (a visitor), so that adding a setting is one line here.
// A visitor provides: field(name, value&, range) for numbers, field(name, value&) for
// booleans, enums and seeds (every value valid), and section(name, settings&) for nested
// structs.
#include <cmath>
#include <limits>
#include <string>

#include "core/enum_names.h"
#include "core/number_format.h"
#include "core/settings/settings.h"
#include "io/value_range.h"

namespace slamkit {

template <class V>
void visit_fields(OrbSettings& s, V& v) {
  v.field("num_features", s.num_features, {1, 100000});
  v.field("pyramid_levels", s.pyramid_levels, {1, 12});
  v.field("scale_factor", s.scale_factor, above(1, 2));
  v.field("fast_type", s.fast_type);
  v.field("fast_threshold", s.fast_threshold, {1, 255});
  v.field("fast_min_threshold", s.fast_min_threshold, {1, 255});
  v.field("spread_over_image", s.spread_over_image);
  v.field("cell_size", s.cell_size, {1, 10000});
  v.field("max_cell_share", s.max_cell_share, above(0));
  v.field("shi_tomasi_block_size", s.shi_tomasi_block_size, {1, 99});
  v.field("edge_threshold", s.edge_threshold, {0, 1000});
}

template <class V>
void visit_fields(MatcherSettings& s, V& v) {
  v.field("backend", s.backend);
  v.field("lsh_table_number", s.lsh_table_number, {1, 100});
  v.field("lsh_key_size", s.lsh_key_size, {1, 32});
  v.field("lsh_multi_probe_level", s.lsh_multi_probe_level, {0, 10});
  v.field("lsh_seed", s.lsh_seed);
  v.field("ratio", s.ratio, above(0, 1));
  v.field("mutual_check", s.mutual_check);
  v.field("max_distance", s.max_distance, {0, 256});
  v.field("projection_radius", s.projection_radius, above(0));
  v.field("projection_max_distance", s.projection_max_distance, {0, 256});
  v.field("projection_ratio", s.projection_ratio, above(0, 1));
  v.field("projection_octave_window", s.projection_octave_window, {0, 12});
  v.field("grid_cell_size", s.grid_cell_size, above(0));
}

template <class V>
void visit_fields(RansacSettings& s, V& v) {
  v.field("threshold_base", s.threshold_base, at_least(0));
  v.field("threshold_quadratic", s.threshold_quadratic, at_least(0));
  v.field("max_iterations", s.max_iterations, at_least(1));
  v.field("confidence", s.confidence, {0, 1});
  v.field("min_sample_spread", s.min_sample_spread, at_least(0));
  v.field("min_sample_shape", s.min_sample_shape, {0, 1});
  v.field("seed", s.seed);
}

template <class V>
void visit_fields(PointToPlaneSettings& s, V& v) {
  v.field("pyramid_levels", s.pyramid_levels, {1, 8});
  v.field("iterations_per_level", s.iterations_per_level, {1, 1000});
  v.field("max_pair_distance", s.max_pair_distance, above(0));
  v.field("max_normal_angle_deg", s.max_normal_angle_deg, {0, 180});
  v.field("max_neighbour_depth_ratio", s.max_neighbour_depth_ratio, {0, 1});
  v.field("central_difference_normals", s.central_difference_normals);
  v.field("convergence_rotation", s.convergence_rotation, at_least(0));
  v.field("convergence_translation", s.convergence_translation, at_least(0));
  v.field("min_correspondences", s.min_correspondences, at_least(1));
  v.field("min_eigenvalue", s.min_eigenvalue, {0, 1});
  v.field("normal_smoothing_diameter", s.normal_smoothing_diameter, {0, 100});
  v.field("normal_smoothing_sigma_depth", s.normal_smoothing_sigma_depth, above(0));
  v.field("photometric_weight", s.photometric_weight, at_least(0));
  v.field("photometric_huber", s.photometric_huber, above(0));
  v.field("photometric_min_gradient", s.photometric_min_gradient, at_least(0));
}

template <class V>
void visit_fields(MotionBaSettings& s, V& v) {
  v.field("rounds", s.rounds, {0, 100});
  v.field("iterations_per_round", s.iterations_per_round, {0, 1000});
  v.field("robust_rounds", s.robust_rounds, {0, 100});
  v.field("chi2_2d", s.chi2_2d, above(0));
  v.field("chi2_3d", s.chi2_3d, above(0));
  v.field("use_depth", s.use_depth);
  v.field("virtual_bf", s.virtual_bf, above(0));
  v.field("min_inliers", s.min_inliers, at_least(0));
  v.field("min_matches_after_dense", s.min_matches_after_dense, at_least(0));
}

template <class V>
void visit_fields(FailureSettings& s, V& v) {
  v.field("max_speed", s.max_speed, above(0));
  v.field("max_angular_speed_deg", s.max_angular_speed_deg, above(0));
  v.field("min_dt", s.min_dt, above(0));
  v.field("min_inliers", s.min_inliers, at_least(0));
  v.field("trusted_inliers", s.trusted_inliers, at_least(0));
  v.field("trusted_inlier_ratio", s.trusted_inlier_ratio, {0, 1});
}

template <class V>
void visit_fields(TrackingSettings& s, V& v) {
  v.field("min_pairs_for_svd", s.min_pairs_for_svd, at_least(3));
  v.field("lost_search_radius_factor", s.lost_search_radius_factor, {1, 100});
  v.field("min_matches_for_box", s.min_matches_for_box, at_least(0));
  v.field("relocalisation_candidates", s.relocalisation_candidates, at_least(0));
  v.section("ransac", s.ransac);
  v.section("point_to_plane", s.point_to_plane);
  v.section("motion_ba", s.motion_ba);
  v.section("failure", s.failure);
}

template <class V>
void visit_fields(KeyframeSettings& s, V& v) {
  v.field("similarity_threshold", s.similarity_threshold, {0, 1});
  v.field("pyramid_levels", s.pyramid_levels, {1, 12});
  v.field("scale_factor", s.scale_factor, above(1, 2));
  v.field("pattern_seed", s.pattern_seed);
  v.field("neighbour_frames", s.neighbour_frames, {0, 100});
  v.field("min_tracked_ratio", s.min_tracked_ratio, {0, 1});
}

template <class V>
void visit_fields(MappingSettings& s, V& v) {
  v.field("covisibility_min_shared", s.covisibility_min_shared, at_least(1));
  v.field("local_map_keyframes", s.local_map_keyframes, at_least(1));
  v.field("cull_after_keyframes", s.cull_after_keyframes, at_least(0));
  v.field("min_observations", s.min_observations, at_least(1));
  v.field("min_found_ratio", s.min_found_ratio, {0, 1});
  v.field("fuse_duplicates", s.fuse_duplicates);
  v.field("fuse_neighbours", s.fuse_neighbours, at_least(0));
  v.field("fuse_radius", s.fuse_radius, at_least(0));
  v.field("fuse_max_distance", s.fuse_max_distance, {0, 256});
  v.field("min_view_cos", s.min_view_cos, {-1, 1});
  v.field("cull_keyframes", s.cull_keyframes);
  v.field("culling_redundancy", s.culling_redundancy, {0, 1});
  v.field("culling_observers", s.culling_observers, {1, 1000});
  v.field("culling_max_depth", s.culling_max_depth, {0, 1000});
}

template <class V>
void visit_fields(BaResidualSettings& s, V& v) {
  v.field("use_depth", s.use_depth);
  v.field("virtual_bf", s.virtual_bf, above(0));
  v.field("chi2_2d", s.chi2_2d, above(0));
  v.field("chi2_3d", s.chi2_3d, above(0));
}

template <class V>
void visit_fields(LocalBaSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("robust_iterations", s.robust_iterations, at_least(0));
  v.field("refine_iterations", s.refine_iterations, at_least(0));
  v.field("fix_points_after_iterations", s.fix_points_after_iterations, at_least(-1));
  v.field("motion_rotation_weight", s.motion_rotation_weight, at_least(0));
  v.field("min_motion", s.min_motion, at_least(0));
  v.field("max_covisible_keyframes", s.max_covisible_keyframes, at_least(0));
  v.field("max_fixed_keyframes", s.max_fixed_keyframes, at_least(0));
  v.field("every_keyframes", s.every_keyframes, at_least(1));
}

template <class V>
void visit_fields(GlobalBaSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("iterations", s.iterations, at_least(0));
  v.field("robust", s.robust);
  v.field("refine_iterations", s.refine_iterations, at_least(0));
  v.field("fix_points_after_iterations", s.fix_points_after_iterations, at_least(-1));
}

template <class V>
void visit_fields(OptimizationSettings& s, V& v) {
  v.field("min_keyframe_points", s.min_keyframe_points, at_least(0));
  v.section("residual", s.residual);
  v.section("local_ba", s.local_ba);
  v.section("global_ba", s.global_ba);
}

template <class V>
void visit_fields(LoopSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("train_on_sequence", s.train_on_sequence);
  v.field("training_keyframe_step", s.training_keyframe_step, at_least(1));
  v.field("recent_keyframes", s.recent_keyframes, at_least(0));
  v.field("min_consistent_neighbours", s.min_consistent_neighbours, at_least(0));
  v.field("consistency_neighbours", s.consistency_neighbours, at_least(1));
  v.field("max_verified", s.max_verified, at_least(1));
  v.field("min_matches", s.min_matches, at_least(3));
  v.field("min_inliers", s.min_inliers, at_least(3));
  v.field("neighbourhood_radius", s.neighbourhood_radius, above(0));
  v.field("neighbourhood_max_distance", s.neighbourhood_max_distance, at_least(0));
  v.field("min_neighbourhood_inliers", s.min_neighbourhood_inliers, at_least(0));
  v.field("max_pose_error", s.max_pose_error, above(0));
  v.field("min_correction", s.min_correction, at_least(0));
  v.field("essential_min_weight", s.essential_min_weight, at_least(1));
  v.field("correction_iterations", s.correction_iterations, at_least(1));
  v.field("fuse_points", s.fuse_points);
  v.field("fuse_radius", s.fuse_radius, above(0));
}

template <class V>
void visit_fields(FusionSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("frame_step", s.frame_step, at_least(0));
  v.field("pixel_stride", s.pixel_stride, at_least(1));
  v.field("keyframe_cache_mb", s.keyframe_cache_mb, at_least(0));
  v.field("max_depth", s.max_depth, above(0));
  v.field("voxel_size", s.voxel_size, above(0));
  v.field("batch_frames", s.batch_frames, at_least(1));
  v.field("remove_outliers", s.remove_outliers);
  v.field("outlier_neighbours", s.outlier_neighbours, at_least(1));
  v.field("outlier_std_ratio", s.outlier_std_ratio, at_least(0));
  v.field("binary_ply", s.binary_ply);
}

template <class V>
void visit_fields(VocabularySettings& s, V& v) {
  v.field("branching", s.branching, {2, 255});
  v.field("depth", s.depth, {1, 10});
  v.field("iterations", s.iterations, {1, 1000});
  v.field("seed", s.seed);
  v.field("frame_step", s.frame_step, {1, 100000});
  v.field("direct_index_level", s.direct_index_level, {0, 10});
}

template <class V>
void visit_fields(PipelineSettings& s, V& v) {
  v.field("threads", s.threads, at_least(0));
  v.field("chunk_frames", s.chunk_frames, at_least(1));
  v.field("evaluate", s.evaluate);
  v.field("lost_frames", s.lost_frames);
}

template <class V>
void visit_fields(Settings& s, V& v) {
  v.section("orb", s.orb);
  v.section("matcher", s.matcher);
  v.section("tracking", s.tracking);
  v.section("keyframes", s.keyframes);
  v.section("mapping", s.mapping);
  v.section("optimization", s.optimization);
  v.section("loop", s.loop);
  v.section("map", s.map);
  v.section("vocabulary", s.vocabulary);
  v.section("pipeline", s.pipeline);
}

// Names of enum values in settings files.
inline constexpr EnumNames<FastType, 2> kFastTypeNames = {
    {{FastType::kFast9, "fast9"}, {FastType::kFast12, "fast12"}}};
inline constexpr EnumNames<MatcherBackend, 2> kMatcherBackendNames = {
    {{MatcherBackend::kFlannLsh, "flann_lsh"}, {MatcherBackend::kBruteForce, "brute_force"}}};
inline constexpr EnumNames<LostFrames, 2> kLostFramesNames = {
    {{LostFrames::kOmit, "omit"}, {LostFrames::kMotionModel, "motion-model"}}};
inline const auto& enum_names(FastType) { return kFastTypeNames; }
inline const auto& enum_names(LostFrames) { return kLostFramesNames; }
inline const auto& enum_names(MatcherBackend) { return kMatcherBackendNames; }

}  // namespace slamkit
