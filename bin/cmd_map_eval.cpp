// slamkit map-eval: judges a map (map.ply, or any PLY point cloud or mesh) against the true
// scene of the synthetic sequence it was made from: accuracy (map point to surface distances)
// and completeness (the share of the surface the groundtruth cameras saw that the map covers).
// A mesh is judged by samples of its surface.
#include <cstdio>
#include <memory>

#include "bin/command.h"
#include "core/error.h"
#include "eval/metrics/metrics_json.h"
#include "eval/run/map_evaluation.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;

struct MapEvalArgs {
  std::string map;
  std::string sequence;
  std::string trajectory;
  std::string json_path;
  synth::MapQualitySettings settings;
};

void run_map_eval(const MapEvalArgs& args) {
  std::optional<fs::path> trajectory;
  if (!args.trajectory.empty()) trajectory = args.trajectory;
  const std::optional<synth::MapQuality> q =
      eval::evaluate_map(args.map, args.sequence, trajectory, args.settings);
  if (!q)
    throw_input_error(args.sequence, std::string("not a synthetic sequence (no ") +
                                         synth::kSyntheticInfoFile +
                                         "): map-eval needs the true scene, made by `slamkit "
                                         "synth`");
  std::printf("map-eval    %s against %s\n", args.map.c_str(), args.sequence.c_str());
  eval::print_map_quality(*q);
  if (!args.json_path.empty()) {
    nlohmann::json update;
    synth::add_map_quality_json(update, *q);
    update["map"]["file"] = args.map;
    eval::merge_into_metrics_file(args.json_path, update);
  }
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<MapEvalArgs>();
  CLI::App* cmd = root.add_subcommand(
      "map-eval", "Judge a map (PLY) against the true scene of a synthetic sequence");
  cmd->add_option("map", args->map,
                  "Map as a PLY point cloud or mesh (its surface sampled), e.g. a run's map.ply")
      ->required();
  cmd->add_option("sequence", args->sequence, "Synthetic sequence folder (from slamkit synth)")
      ->required();
  cmd->add_option("--trajectory", args->trajectory,
                  "The run's trajectory.txt: the map is in its world frame and is aligned to "
                  "groundtruth as ATE aligns the trajectory (without it: already in the "
                  "groundtruth frame)");
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
