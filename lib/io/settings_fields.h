#pragma once
// The one list of every settings field with its YAML name, walked by the reader and the
// writer alike (a visitor), so that adding a setting is one line here.
// A visitor provides: field(name, value&) for numbers, booleans and enums, and
// section(name, callable) for nested structs.
#include <string>

#include "core/enum_names.h"
#include "core/settings/settings.h"

namespace slamkit {

template <class V>
void visit_fields(OrbSettings& s, V& v) {
  v.field("num_features", s.num_features);
  v.field("pyramid_levels", s.pyramid_levels);
  v.field("scale_factor", s.scale_factor);
  v.field("fast_type", s.fast_type);
  v.field("fast_threshold", s.fast_threshold);
  v.field("fast_min_threshold", s.fast_min_threshold);
  v.field("spread_over_image", s.spread_over_image);
  v.field("cell_size", s.cell_size);
  v.field("max_cell_share", s.max_cell_share);
  v.field("shi_tomasi_block_size", s.shi_tomasi_block_size);
  v.field("edge_threshold", s.edge_threshold);
}

template <class V>
void visit_fields(MatcherSettings& s, V& v) {
  v.field("backend", s.backend);
  v.field("lsh_table_number", s.lsh_table_number);
  v.field("lsh_key_size", s.lsh_key_size);
  v.field("lsh_multi_probe_level", s.lsh_multi_probe_level);
  v.field("lsh_seed", s.lsh_seed);
  v.field("ratio", s.ratio);
  v.field("mutual_check", s.mutual_check);
  v.field("max_distance", s.max_distance);
  v.field("projection_radius", s.projection_radius);
  v.field("projection_max_distance", s.projection_max_distance);
  v.field("projection_ratio", s.projection_ratio);
  v.field("projection_octave_window", s.projection_octave_window);
  v.field("grid_cell_size", s.grid_cell_size);
}

template <class V>
void visit_fields(RansacSettings& s, V& v) {
  v.field("threshold_base", s.threshold_base);
  v.field("threshold_quadratic", s.threshold_quadratic);
  v.field("max_iterations", s.max_iterations);
  v.field("confidence", s.confidence);
  v.field("min_sample_spread", s.min_sample_spread);
  v.field("min_sample_shape", s.min_sample_shape);
  v.field("seed", s.seed);
}

template <class V>
void visit_fields(PointToPlaneSettings& s, V& v) {
  v.field("pyramid_levels", s.pyramid_levels);
  v.field("iterations_per_level", s.iterations_per_level);
  v.field("max_pair_distance", s.max_pair_distance);
  v.field("max_normal_angle_deg", s.max_normal_angle_deg);
  v.field("max_neighbour_depth_ratio", s.max_neighbour_depth_ratio);
  v.field("central_difference_normals", s.central_difference_normals);
  v.field("convergence_rotation", s.convergence_rotation);
  v.field("convergence_translation", s.convergence_translation);
  v.field("min_correspondences", s.min_correspondences);
  v.field("min_eigenvalue", s.min_eigenvalue);
  v.field("normal_smoothing_diameter", s.normal_smoothing_diameter);
  v.field("normal_smoothing_sigma_depth", s.normal_smoothing_sigma_depth);
}

template <class V>
void visit_fields(MotionBaSettings& s, V& v) {
  v.field("rounds", s.rounds);
  v.field("iterations_per_round", s.iterations_per_round);
  v.field("robust_rounds", s.robust_rounds);
  v.field("chi2_2d", s.chi2_2d);
  v.field("chi2_3d", s.chi2_3d);
  v.field("use_depth", s.use_depth);
  v.field("virtual_bf", s.virtual_bf);
  v.field("min_inliers", s.min_inliers);
  v.field("min_matches_after_dense", s.min_matches_after_dense);
}

template <class V>
void visit_fields(FailureSettings& s, V& v) {
  v.field("max_speed", s.max_speed);
  v.field("max_angular_speed_deg", s.max_angular_speed_deg);
  v.field("min_dt", s.min_dt);
  v.field("min_inliers", s.min_inliers);
}

template <class V>
void visit_fields(TrackingSettings& s, V& v) {
  v.field("min_pairs_for_svd", s.min_pairs_for_svd);
  v.field("lost_search_radius_factor", s.lost_search_radius_factor);
  v.field("min_matches_for_box", s.min_matches_for_box);
  v.field("relocalisation_candidates", s.relocalisation_candidates);
  v.section("ransac", s.ransac);
  v.section("point_to_plane", s.point_to_plane);
  v.section("motion_ba", s.motion_ba);
  v.section("failure", s.failure);
}

template <class V>
void visit_fields(KeyframeSettings& s, V& v) {
  v.field("similarity_threshold", s.similarity_threshold);
  v.field("pyramid_levels", s.pyramid_levels);
  v.field("scale_factor", s.scale_factor);
  v.field("pattern_seed", s.pattern_seed);
  v.field("neighbour_frames", s.neighbour_frames);
  v.field("min_tracked_ratio", s.min_tracked_ratio);
}

template <class V>
void visit_fields(MappingSettings& s, V& v) {
  v.field("covisibility_min_shared", s.covisibility_min_shared);
  v.field("local_map_keyframes", s.local_map_keyframes);
  v.field("cull_after_keyframes", s.cull_after_keyframes);
  v.field("min_observations", s.min_observations);
  v.field("min_found_ratio", s.min_found_ratio);
  v.field("fuse_duplicates", s.fuse_duplicates);
  v.field("fuse_neighbours", s.fuse_neighbours);
  v.field("fuse_radius", s.fuse_radius);
  v.field("fuse_max_distance", s.fuse_max_distance);
  v.field("min_view_cos", s.min_view_cos);
}

template <class V>
void visit_fields(BaResidualSettings& s, V& v) {
  v.field("use_depth", s.use_depth);
  v.field("virtual_bf", s.virtual_bf);
  v.field("chi2_2d", s.chi2_2d);
  v.field("chi2_3d", s.chi2_3d);
}

template <class V>
void visit_fields(LocalBaSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("robust_iterations", s.robust_iterations);
  v.field("refine_iterations", s.refine_iterations);
  v.field("fix_points_after_iterations", s.fix_points_after_iterations);
  v.field("motion_rotation_weight", s.motion_rotation_weight);
  v.field("min_motion", s.min_motion);
  v.field("max_covisible_keyframes", s.max_covisible_keyframes);
  v.field("max_fixed_keyframes", s.max_fixed_keyframes);
  v.field("every_keyframes", s.every_keyframes);
}

template <class V>
void visit_fields(GlobalBaSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("iterations", s.iterations);
  v.field("robust", s.robust);
  v.field("refine_iterations", s.refine_iterations);
}

template <class V>
void visit_fields(OptimizationSettings& s, V& v) {
  v.field("min_keyframe_points", s.min_keyframe_points);
  v.section("residual", s.residual);
  v.section("local_ba", s.local);
  v.section("global_ba", s.global);
}

template <class V>
void visit_fields(FusionSettings& s, V& v) {
  v.field("enabled", s.enabled);
  v.field("frame_step", s.frame_step);
  v.field("pixel_stride", s.pixel_stride);
  v.field("max_depth", s.max_depth);
  v.field("voxel_size", s.voxel_size);
  v.field("batch_frames", s.batch_frames);
  v.field("remove_outliers", s.remove_outliers);
  v.field("outlier_neighbours", s.outlier_neighbours);
  v.field("outlier_std_ratio", s.outlier_std_ratio);
  v.field("binary_ply", s.binary_ply);
}

template <class V>
void visit_fields(PipelineSettings& s, V& v) {
  v.field("threads", s.threads);
  v.field("chunk_frames", s.chunk_frames);
  v.field("evaluate", s.evaluate);
}

template <class V>
void visit_fields(Settings& s, V& v) {
  v.section("orb", s.orb);
  v.section("matcher", s.matcher);
  v.section("tracking", s.tracking);
  v.section("keyframes", s.keyframes);
  v.section("mapping", s.mapping);
  v.section("optimization", s.optimization);
  v.section("map", s.fusion);
  v.section("pipeline", s.pipeline);
}

// Names of enum values in settings files.
inline constexpr EnumNames<FastType, 2> kFastTypeNames = {
    {{FastType::kFast9, "fast9"}, {FastType::kFast12, "fast12"}}};
inline constexpr EnumNames<MatcherBackend, 2> kMatcherBackendNames = {
    {{MatcherBackend::kFlannLsh, "flann_lsh"}, {MatcherBackend::kBruteForce, "brute_force"}}};
inline const auto& enum_names(FastType) { return kFastTypeNames; }
inline const auto& enum_names(MatcherBackend) { return kMatcherBackendNames; }

}  // namespace slamkit
