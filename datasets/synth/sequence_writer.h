#pragma once
// Renders a preset into a folder in the TUM RGB-D layout: rgb/<stamp>.png, depth/<stamp>.png,
// rgb.txt, depth.txt, associate.txt, groundtruth.txt (the exact poses), revisits.txt (which
// frames truly revisit a place, revisits.h), calibration.yaml and synthetic.yaml (the preset
// and seed, so that tools can rebuild the scene).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "core/camera.h"
#include "datasets/synth/kinect_sensor.h"
#include "datasets/synth/scene.h"
#include "datasets/synth/sensor_model.h"
#include "datasets/synth/trajectory_presets.h"

namespace slamkit::synth {

struct SequenceSpec {
  Preset preset = Preset::kDesk;
  int frames = 600;
  // Only frames [0, first_frames) of the `frames`-long motion are written (0: all): the start
  // of a long sequence at its own speed, without rendering the rest.
  int first_frames = 0;
  uint64_t seed = 1;
  int threads = 0;  // OpenMP threads rendering frames; 0 = OpenMP's default
  std::filesystem::path out;
  SensorModel sensor;  // the ideal sensor's noise
  // The kinect sensor instead (--sensor kinect): blur, rolling shutter, depth on its own clock
  // (depth.txt's stamps differ from rgb.txt's, groundtruth.txt at 100 Hz), docs/sensor.md.
  std::optional<KinectSettings> kinect;
};

// Freiburg-like pinhole camera without distortion: fx = fy = 525, cx 319.5, cy 239.5,
// 640 x 480, depth in 1/5000 m.
Camera synthetic_camera();

// Frame i is taken at 1600000000 + i / 30 s, rounded to the microsecond: the text is what
// the lists say, the double is exactly what reading that text gives.
std::string frame_stamp_text(int i);
double frame_stamp(int i);

// Throws InputError naming the option at fault (preset-independent checks: frames, threads,
// the kinect settings).
void check_spec(const SequenceSpec& spec);

// Writes the whole sequence (frames rendered in parallel, identical for any thread count).
// on_progress(frames_done) is called on the calling thread. `scene` must be the one the
// preset films (preset_scene; std::invalid_argument otherwise). Throws InputError when the
// spec is invalid or a file cannot be written.
void write_sequence(const SyntheticScene& scene, const SequenceSpec& spec,
                    const std::function<void(size_t)>& on_progress = nullptr);

}  // namespace slamkit::synth
