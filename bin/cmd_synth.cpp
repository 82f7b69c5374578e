// slamkit synth: renders a synthetic TUM-layout RGB-D sequence with exact groundtruth.
#include <chrono>
#include <cstdio>
#include <memory>

#include "bin/command.h"
#include "bin/output_folder.h"
#include "core/progress.h"
#include "datasets/synth/room_layout.h"
#include "datasets/synth/sensor_choice.h"
#include "datasets/synth/sequence_writer.h"

namespace slamkit::cli {
namespace {

struct SynthArgs {
  std::string preset = "desk";
  int frames = 600;
  uint64_t seed = 1;
  int threads = 0;
  std::string out;
  synth::SensorChoice sensor;
};

void run_synth(const SynthArgs& args) {
  check_output_folder("--out", args.out);
  const auto start = std::chrono::steady_clock::now();
  synth::SequenceSpec spec;
  spec.preset = synth::parse_preset(args.preset);
  spec.frames = args.frames;
  spec.seed = args.seed;
  spec.threads = args.threads;
  spec.out = args.out;
  spec.kinect = synth::kinect_settings(args.sensor);
  synth::check_spec(spec);  // before the scene's textures are built: bad arguments fail at once

  const synth::SyntheticScene scene = synth::make_named_scene(synth::preset_scene(spec.preset));
  Progress progress("synth " + args.preset, size_t(spec.frames));
  synth::write_sequence(scene, spec, [&progress](size_t done) { progress.update(done); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("synth: %d frames of '%s' (seed %llu, %s sensor) in %.1f s -> %s\n", spec.frames,
              args.preset.c_str(), static_cast<unsigned long long>(spec.seed),
              args.sensor.sensor.c_str(), seconds, spec.out.string().c_str());
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* cmd = root.add_subcommand(
      "synth", "Render a synthetic RGB-D sequence (TUM layout, exact groundtruth)");
  cmd->add_option("--preset", args->preset, "Camera motion: desk, loop, lowtexture, jerk, long or lookalike")
      ->capture_default_str();
  cmd->add_option("--frames", args->frames, "Number of frames (30 Hz)")->capture_default_str();
  cmd->add_option("--out", args->out, "Output folder (created if missing)")->required();
  cmd->add_option("--seed", args->seed, "Seed of the hand shake and the sensor noise")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Rendering threads (0 = all cores)")
      ->capture_default_str();
  std::string effects;
  for (const std::string& name : synth::kinect_effect_names())
    effects += (effects.empty() ? "" : ", ") + name;
  cmd->add_option("--sensor", args->sensor.sensor,
                  "Sensor: ideal (exact stamps, no blur, Gaussian noise) or kinect (Kinect v1 "
                  "effects, see docs/sensor.md)")
      ->capture_default_str();
  cmd->add_option("--sensor-off", args->sensor.effects_off,
                  "Kinect effects to turn off, comma-separated: " + effects);
  cmd->add_option("--sensor-on", args->sensor.effects_on,
                  "Kinect effects to turn on (lens_distortion is off by default)");
  cmd->add_option("--sensor-settings", args->sensor.settings_file,
                  "YAML file of kinect settings, as synthetic.yaml's `kinect:` map (keys left "
                  "out keep their defaults)");
  cmd->callback([args] { run_synth(*args); });
});

}  // namespace
}  // namespace slamkit::cli
