// slamkit fuse SEQ --trajectory FILE --out DIR: the map of a sequence along any trajectory (a
// run's, another system's, or groundtruth): the frames with a pose are fused as `run` fuses
// its keyframes (docs/method.md#map-fusion) into DIR/map.ply (and mesh.ply with --mesh).
#include <omp.h>

#include <cstdio>
#include <limits>
#include <memory>

#include "bin/command.h"
#include "bin/sequence_options.h"
#include "core/error.h"
#include "core/settings/settings.h"
#include "fusion/map_fusion.h"
#include "settings/settings_yaml.h"
#include "io/trajectory_io.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;

struct FuseArgs {
  std::string folder;
  std::string trajectory;
  std::string out;
  std::string settings_file;
  int threads = -1;
  int frame_step = 1;
  double max_difference = 0.02;
  bool mesh = false;
  bool ascii = false;
  SequenceOptions sequence;
};

// Every frame_step-th frame that has a pose within max_difference seconds of its stamp.
std::vector<FusionFrame> frames_with_poses(const TumSequence& seq, const Trajectory& poses,
                                           const FuseArgs& args) {
  std::vector<FusionFrame> frames;
  for (size_t i = 0; i < seq.size(); i += size_t(args.frame_step))
    if (const auto k = poses.nearest(seq.stamp(i), args.max_difference))
      frames.push_back({i, poses[*k].T_w_c, nullptr});
  return frames;
}

void fuse(const FuseArgs& args) {
  Settings settings;
  if (!args.settings_file.empty()) read_settings_yaml(args.settings_file, settings);
  if (args.mesh) settings.map.mesh = true;
  if (args.ascii) settings.map.binary_ply = false;
  omp_set_num_threads(args.threads > 0 ? args.threads : omp_get_num_procs());
  const TumSequence seq = TumSequence::open(args.folder, args.sequence);
  const Trajectory poses = read_tum_trajectory(args.trajectory).trajectory;
  const std::vector<FusionFrame> frames = frames_with_poses(seq, poses, args);
  if (frames.empty())
    throw_input_error(args.trajectory, "no pose within " + std::to_string(args.max_difference) +
                                           " s of any frame of " + seq.folder().string());
  const fs::path out(args.out);
  const FusionReport r =
      fuse_map(seq, frames, settings.map, out / "map.ply", out / "mesh.ply");
  if (r.method == MapMethod::kTsdf)
    std::printf("fused map   %zu frames: %zu depth samples into a %.0f mm TSDF (%zu blocks, %.0f MB), "
                "%zu surface points, %zu triangles, %.2f s\n",
                r.frames, r.raw_points, settings.map.voxel_size * 1000, r.blocks, r.volume_mb,
                r.points, r.triangles, r.seconds);
  else
    std::printf("fused map   %zu frames: %zu points raw, %zu voxels, %zu points kept, %.2f s\n",
                r.frames, r.raw_points, r.after_voxel_grid, r.points, r.seconds);
  std::printf("map         %s\n", (out / "map.ply").c_str());
  if (r.triangles > 0) std::printf("mesh        %s\n", (out / "mesh.ply").c_str());
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<FuseArgs>();
  CLI::App* cmd = root.add_subcommand(
      "fuse", "Fuse a map (map.ply, mesh.ply) of a TUM sequence along a given trajectory");
  cmd->add_option("sequence", args->folder, "Sequence folder (TUM layout)")->required();
  cmd->add_option("--trajectory", args->trajectory,
                  "TUM trajectory (camera to world), e.g. a run's trajectory.txt or keyframes.txt")
      ->required();
  cmd->add_option("--out", args->out, "Folder to write map.ply (and mesh.ply) into")->required();
  cmd->add_option("--settings", args->settings_file, "Settings YAML (its map: section is used)");
  cmd->add_option("--frame-step", args->frame_step, "Every n-th frame of the sequence")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()))
      ->capture_default_str();
  cmd->add_option("--max-difference", args->max_difference,
                  "A frame takes the pose nearest its stamp within this many seconds")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads (0 = all cores)")
      ->check(CLI::Range(0, std::numeric_limits<int>::max()));
  cmd->add_flag("--mesh", args->mesh, "Also write mesh.ply (marching cubes)");
  cmd->add_flag("--ascii", args->ascii, "Write ASCII PLY (default: binary)");
  add_sequence_options(cmd, args->sequence);
  cmd->callback([args] { fuse(*args); });
});

}  // namespace
}  // namespace slamkit::cli
