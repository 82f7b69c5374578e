#pragma once
// The sensor of `slamkit synth` (and slamkit.synth in Python) from its options: ideal, or
// kinect with its defaults, then a settings file, then effects switched off and on.
#include <optional>
#include <string>

#include "datasets/synth/kinect_sensor.h"

namespace slamkit::synth {

struct SensorChoice {
  std::string sensor = "ideal";         // ideal or kinect
  std::string settings_file;            // YAML of kinect settings (synthetic.yaml's `kinect:` map)
  std::string effects_off, effects_on;  // comma-separated effect names
};

// nullopt for the ideal sensor. Throws InputError naming the option at fault (in the CLI's
// words: --sensor, --sensor-settings, --sensor-off, --sensor-on).
std::optional<KinectSettings> kinect_settings(const SensorChoice& choice);

}  // namespace slamkit::synth
