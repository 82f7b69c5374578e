#include "datasets/synth/sensor_choice.h"

#include "core/error.h"
#include "io/yaml_file.h"

namespace slamkit::synth {

std::optional<KinectSettings> kinect_settings(const SensorChoice& choice) {
  if (choice.sensor == "ideal") {
    if (!choice.settings_file.empty() || !choice.effects_off.empty() || !choice.effects_on.empty())
      throw InputError("--sensor-settings, --sensor-off and --sensor-on need --sensor kinect");
    return std::nullopt;
  }
  if (choice.sensor != "kinect")
    throw InputError("--sensor: unknown sensor '" + choice.sensor + "' (ideal or kinect)");
  KinectSettings settings;
  if (!choice.settings_file.empty())
    settings = read_kinect_settings(load_yaml_file(choice.settings_file, "sensor settings"),
                                    choice.settings_file);
  switch_effects(settings, choice.effects_off, false, "--sensor-off");
  switch_effects(settings, choice.effects_on, true, "--sensor-on");
  return settings;
}

}  // namespace slamkit::synth
