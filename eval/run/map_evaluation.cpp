#include "eval/run/map_evaluation.h"

#include <cstdio>

#include "core/error.h"
#include "eval/metrics/alignment.h"
#include "eval/metrics/association.h"
#include "eval/run/map_points.h"
#include "io/trajectory_io.h"
#include "io/tum_sequence.h"

namespace slamkit::eval {
namespace {

// The groundtruth pose of each frame, in frame order (frames without one are left out).
std::vector<Eigen::Isometry3d> groundtruth_poses(const TumSequence& sequence) {
  const Trajectory& gt = *sequence.groundtruth();
  std::vector<Eigen::Isometry3d> poses;
  for (size_t i = 0; i < sequence.size(); ++i)
    if (const auto k = gt.nearest(sequence.stamp(i), 0.02)) poses.push_back(gt[*k].T_w_c);
  return poses;
}

void align_into_groundtruth(std::vector<Eigen::Vector3f>& points, const Trajectory& gt,
                            const std::filesystem::path& trajectory) {
  const Trajectory est = read_tum_trajectory(trajectory).trajectory;
  const AssociationOptions options;
  require_associable(gt, est, "groundtruth", trajectory.string(), options);
  const auto pairs = associate(gt, est, options);
  require_enough_pairs(pairs.size(), gt, est, "groundtruth", trajectory.string(), options);
  const Alignment alignment =
      align(gt, est, pairs, AlignMethod::kSe3, 0, "groundtruth", trajectory.string());
  for (Eigen::Vector3f& p : points) p = alignment.apply(p.cast<double>()).cast<float>();
}

}  // namespace

std::optional<synth::MapQuality> evaluate_map(
    const std::filesystem::path& map, const std::filesystem::path& sequence_folder,
    const std::optional<std::filesystem::path>& trajectory,
    const synth::MapQualitySettings& settings) {
  const std::optional<synth::SyntheticInfo> info = synth::read_synthetic_info(sequence_folder);
  if (!info) return std::nullopt;
  const TumSequence sequence = TumSequence::open(sequence_folder);
  if (!sequence.groundtruth())
    throw_input_error((sequence_folder / "groundtruth.txt").string(), "not found");
  MapPoints map_points = read_map_points(map);
  if (trajectory) align_into_groundtruth(map_points.points, *sequence.groundtruth(), *trajectory);
  synth::MapQuality quality =
      synth::evaluate_map_quality(map_points.points, synth::make_scene(*info),
                                  groundtruth_poses(sequence), sequence.camera(), settings);
  quality.mesh_triangles = map_points.mesh_triangles;
  return quality;
}

void print_map_quality(const synth::MapQuality& q) {
  const synth::MapQualitySettings& s = q.settings;
  if (q.mesh_triangles > 0)
    std::printf(
        "map mesh    judged a mesh of %zu triangles sampled as %zu points (its vertices and "
        "samples at most %.1f mm apart)\n",
        q.mesh_triangles, q.map_points, 1000 * kMeshSampleSpacing);
  std::printf(
      "map quality accuracy (distance to the true surface of %zu points): mean %.1f mm, median "
      "%.1f mm, p95 %.1f mm, max %.1f mm\n",
      q.map_points, 1000 * q.accuracy_mean, 1000 * q.accuracy_median, 1000 * q.accuracy_p95,
      1000 * q.accuracy_max);
  std::printf(
      "            completeness %.1f %% of %zu visible surface samples within %.0f mm (every "
      "%d-th of %zu views, pixel stride %d, depth %.1f-%.1f m)\n",
      100.0 * q.completeness, q.surface_samples, 1000 * s.radius, s.frame_step, q.views,
      s.pixel_stride, s.min_depth, s.max_depth);
}

}  // namespace slamkit::eval
