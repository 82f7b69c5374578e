#pragma once
// Map quality of a map (point cloud or mesh) made from a synthetic sequence (`slamkit
// map-eval`, and `slamkit run` on synthetic input): accuracy and completeness against the true
// scene.
#include <filesystem>
#include <optional>

#include "datasets/synth/map_quality.h"

namespace slamkit::eval {

// nullopt when `sequence` is not synthetic (no synthetic.yaml). The map is a PLY point cloud
// or mesh, read and checked by read_map_points (map_points.h). A map made in the estimate's
// own world frame (a run's map.ply: the first camera is the origin) is first brought into the
// groundtruth frame by the SE(3) alignment of `trajectory` to groundtruth (ATE's alignment);
// without a trajectory the map must already be in the groundtruth frame.
std::optional<synth::MapQuality> evaluate_map(
    const std::filesystem::path& map, const std::filesystem::path& sequence,
    const std::optional<std::filesystem::path>& trajectory,
    const synth::MapQualitySettings& settings);

void print_map_quality(const synth::MapQuality& quality);

}  // namespace slamkit::eval
