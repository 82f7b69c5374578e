// slamkit map-eval: judges a point-cloud map (map.ply) against the true scene of the synthetic
// sequence it was made from: accuracy (map point to surface distances) and completeness (the
// share of the surface the groundtruth cameras saw that the map covers).
#include <cstdio>
#include <memory>

#include "bin/command.h"
#include "core/error.h"
#include "datasets/synth/map_quality.h"
#include "eval/metrics_json.h"
#include "fusion/ply_cloud.h"
#include "io/tum_sequence.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;

struct MapEvalArgs {
  std::string map;
  std::string sequence;
  std::string json_path;
  synth::MapQualitySettings settings;
};

// The groundtruth pose of each frame, in frame order (frames without one are left out).
std::vector<Eigen::Isometry3d> groundtruth_poses(const TumSequence& sequence) {
  const Trajectory& gt = *sequence.groundtruth();
  std::vector<Eigen::Isometry3d> poses;
  for (size_t i = 0; i < sequence.size(); ++i)
    if (const auto k = gt.nearest(sequence.stamp(i), 0.02)) poses.push_back(gt[*k].T_w_c);
  return poses;
}

void run_map_eval(const MapEvalArgs& args) {
  const std::optional<synth::SyntheticInfo> info = synth::read_synthetic_info(args.sequence);
  if (!info)
    throw_input_error(args.sequence, std::string("not a synthetic sequence (no ") +
                                         synth::kSyntheticInfoFile +
                                         "): map-eval needs the true scene, made by `slamkit "
                                         "synth`");
  const TumSequence sequence = TumSequence::open(args.sequence);
  if (!sequence.groundtruth())
    throw_input_error((fs::path(args.sequence) / "groundtruth.txt").string(), "not found");
  const std::vector<Eigen::Isometry3d> poses = groundtruth_poses(sequence);
  const std::vector<Eigen::Vector3f> points = read_ply_points(args.map);

  const synth::SyntheticScene scene = synth::make_scene(*info);
  const synth::MapQuality q =
      synth::evaluate_map_quality(points, scene, poses, sequence.camera(), args.settings);
  const synth::MapQualitySettings& s = q.settings;
  std::printf("map-eval: %s, %zu points, against %s (%s, %d frames, seed %llu)\n", args.map.c_str(),
              q.map_points, args.sequence.c_str(), synth::preset_name(info->preset).c_str(),
              info->frames, static_cast<unsigned long long>(info->seed));
  std::printf(
      "accuracy (distance to the true surface): mean %.4f m, median %.4f m, "
      "p95 %.4f m, max %.4f m\n",
      q.accuracy_mean, q.accuracy_median, q.accuracy_p95, q.accuracy_max);
  std::printf(
      "completeness: %.1f %% of %zu visible surface samples within %.3f m (frame step "
      "%d over %zu frames, pixel stride %d, depth %.1f-%.1f m)\n",
      100.0 * q.completeness, q.surface_samples, s.radius, s.frame_step, poses.size(),
      s.pixel_stride, s.min_depth, s.max_depth);
  if (!args.json_path.empty()) {
    nlohmann::json update;
    synth::add_map_quality_json(update, q);
    update["map"]["file"] = args.map;
    eval::merge_into_metrics_file(args.json_path, update);
  }
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<MapEvalArgs>();
  CLI::App* cmd = root.add_subcommand(
      "map-eval", "Judge a map (PLY) against the true scene of a synthetic sequence");
  cmd->add_option("map", args->map, "Point-cloud map (PLY), e.g. a run's map.ply")->required();
  cmd->add_option("sequence", args->sequence, "Synthetic sequence folder (from slamkit synth)")
      ->required();
  cmd->add_option("--json", args->json_path, "Write the numbers under \"map\" (merged into it)");
  synth::MapQualitySettings& s = args->settings;
  cmd->add_option("--frame-step", s.frame_step, "Sample the visible surface every n-th frame")
      ->capture_default_str();
  cmd->add_option("--pixel-stride", s.pixel_stride, "... through every n-th pixel")
      ->capture_default_str();
  cmd->add_option("--max-depth", s.max_depth, "... up to this depth (fusion's max_depth), m")
      ->capture_default_str();
  cmd->add_option("--radius", s.radius, "A surface sample is covered within this distance, m")
      ->capture_default_str();
  cmd->callback([args] { run_map_eval(*args); });
});

}  // namespace
}  // namespace slamkit::cli
