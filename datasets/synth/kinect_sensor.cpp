#include "datasets/synth/kinect_sensor.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include <yaml-cpp/yaml.h>

#include "core/depth_noise.h"
#include "core/error.h"

namespace slamkit::synth {

const std::vector<std::string>& kinect_effect_names() {
  static const std::vector<std::string> kNames = {
      "motion_blur",  "rolling_shutter",    "stream_timing", "colour_noise",
      "auto_exposure", "vignetting",        "lens_distortion", "depth_quantisation",
      "depth_noise",  "depth_edges",        "projector_shadow", "misregistration"};
  return kNames;
}

std::vector<bool> KinectSettings::default_effects() {
  std::vector<bool> on(size_t(KinectEffect::kCount), true);
  // Distorted colour needs a reader that undistorts: opt in.
  on[size_t(KinectEffect::kLensDistortion)] = false;
  return on;
}

double KinectSettings::axial_sigma(double z, double theta) { return kinect_axial_sigma(z, theta); }

double KinectSettings::lateral_sigma_px(double theta) {
  const double t = std::min(theta, 80.0 * M_PI / 180.0);
  return 0.8 + 0.035 * t / (M_PI / 2 - t);
}

double KinectSettings::depth_step(double z) const {
  return z * z * disparity_step_px / (ir_focal_px * baseline_m);
}

double KinectSettings::quantise_depth(double z) const {
  const double fb = ir_focal_px * baseline_m;
  const double levels = std::round(fb / z / disparity_step_px);
  return levels > 0 ? fb / (levels * disparity_step_px) : 0.0;
}

namespace {

// Every number of the settings by name, for synthetic.yaml.
std::vector<std::pair<const char*, double*>> numbers(KinectSettings& s) {
  return {{"exposure_s", &s.exposure_s},
          {"readout_s", &s.readout_s},
          {"blur_step_px", &s.blur_step_px},
          {"depth_offset_s", &s.depth_offset_s},
          {"depth_drift", &s.depth_drift},
          {"depth_jitter_s", &s.depth_jitter_s},
          {"groundtruth_rate_hz", &s.groundtruth_rate_hz},
          {"read_noise", &s.read_noise},
          {"shot_gain", &s.shot_gain},
          {"exposure_drift", &s.exposure_drift},
          {"vignetting", &s.vignetting},
          {"k1", &s.k1},
          {"k2", &s.k2},
          {"p1", &s.p1},
          {"p2", &s.p2},
          {"k3", &s.k3},
          {"baseline_m", &s.baseline_m},
          {"ir_focal_px", &s.ir_focal_px},
          {"disparity_step_px", &s.disparity_step_px},
          {"min_range_m", &s.min_range_m},
          {"max_range_m", &s.max_range_m},
          {"max_incidence_deg", &s.max_incidence_deg},
          {"dropout_probability", &s.dropout_probability},
          {"edge_jump", &s.edge_jump},
          {"edge_flying", &s.edge_flying},
          {"edge_missing", &s.edge_missing},
          {"misregistration_m", &s.misregistration_m},
          {"misregistration_deg", &s.misregistration_deg}};
}

std::vector<std::pair<const char*, int*>> integers(KinectSettings& s) {
  return {{"max_subframes", &s.max_subframes}, {"holes_per_frame", &s.holes_per_frame}};
}

}  // namespace

void emit_kinect_settings(YAML::Emitter& out, const KinectSettings& settings) {
  KinectSettings s = settings;  // numbers() hands out pointers into a copy
  out << YAML::BeginMap << YAML::Key << "effects" << YAML::Value << YAML::BeginMap;
  for (size_t e = 0; e < kinect_effect_names().size(); ++e)
    out << YAML::Key << kinect_effect_names()[e] << YAML::Value << bool(s.on[e]);
  out << YAML::EndMap;
  for (const auto& [name, value] : numbers(s)) out << YAML::Key << name << YAML::Value << *value;
  for (const auto& [name, value] : integers(s)) out << YAML::Key << name << YAML::Value << *value;
  out << YAML::EndMap;
}

KinectSettings read_kinect_settings(const YAML::Node& node, const std::string& file) {
  KinectSettings s;
  if (!node.IsMap()) throw_input_error(file, node.Mark().line + 1, "kinect: expected a map");
  const auto numbers_of_s = numbers(s);
  const auto integers_of_s = integers(s);
  for (const auto& kv : node) {
    const std::string key = kv.first.as<std::string>();
    const int line = kv.first.Mark().line + 1;
    try {
      if (key == "effects") {
        if (!kv.second.IsMap()) throw_input_error(file, line, "kinect.effects: expected a map");
        for (const auto& effect : kv.second) {
          const std::string name = effect.first.as<std::string>();
          if (name.find(',') != std::string::npos)
            throw_input_error(file, line, "kinect.effects: one effect per key, got '" + name + "'");
          try {
            switch_effects(s, name, effect.second.as<bool>(), "kinect.effects");
          } catch (const InputError& e) {
            throw_input_error(file, effect.first.Mark().line + 1, e.what());
          }
        }
        continue;
      }
      bool known = false;
      for (const auto& [name, value] : numbers_of_s)
        if (key == name) *value = kv.second.as<double>(), known = true;
      for (const auto& [name, value] : integers_of_s)
        if (key == name) *value = kv.second.as<int>(), known = true;
      if (!known) throw_input_error(file, line, "kinect: unknown setting '" + key + "'");
    } catch (const YAML::Exception& e) {
      throw_input_error(file, line, "kinect." + key + ": " + e.msg);
    }
  }
  return s;
}

void check_kinect_settings(const KinectSettings& s) {
  const auto require = [](bool ok, const std::string& what) {
    if (!ok) throw InputError("kinect sensor: " + what);
  };
  require(s.exposure_s >= 0 && s.exposure_s < 1, "exposure_s must be in [0, 1) s");
  require(s.readout_s >= 0 && s.readout_s < 1, "readout_s must be in [0, 1) s");
  require(s.blur_step_px > 0, "blur_step_px must be positive");
  require(s.max_subframes >= 1 && s.max_subframes <= 256, "max_subframes must be 1..256");
  require(std::abs(s.depth_offset_s) < 1, "depth_offset_s must be within 1 s");
  require(s.depth_drift > -0.5 && s.depth_drift < 0.5, "depth_drift must be within +-0.5");
  require(s.depth_jitter_s >= 0 && s.depth_jitter_s < 0.01, "depth_jitter_s must be in [0, 0.01) s");
  require(s.groundtruth_rate_hz >= 1 && s.groundtruth_rate_hz <= 10000,
          "groundtruth_rate_hz must be 1..10000");
  require(s.read_noise >= 0 && s.shot_gain >= 0 && s.exposure_drift >= 0,
          "read_noise, shot_gain and exposure_drift must not be negative");
  require(s.vignetting >= 0 && s.vignetting < 1, "vignetting must be in [0, 1)");
  require(s.baseline_m > 0 && s.ir_focal_px > 0 && s.disparity_step_px > 0,
          "baseline_m, ir_focal_px and disparity_step_px must be positive");
  require(s.min_range_m >= 0 && s.max_range_m > s.min_range_m,
          "need 0 <= min_range_m < max_range_m");
  require(s.max_incidence_deg > 0 && s.max_incidence_deg <= 90, "max_incidence_deg must be 0..90");
  require(s.dropout_probability >= 0 && s.dropout_probability <= 1 && s.edge_flying >= 0 &&
              s.edge_missing >= 0 && s.edge_flying + s.edge_missing <= 1,
          "dropout_probability, edge_flying and edge_missing are probabilities (the last two "
          "summing to at most 1)");
  require(s.edge_jump > 0, "edge_jump must be positive");
  require(s.holes_per_frame >= 0, "holes_per_frame must not be negative");
}

void switch_effects(KinectSettings& settings, const std::string& list, bool on,
                    const std::string& option) {
  const auto& names = kinect_effect_names();
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name.empty()) continue;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      std::string valid;
      for (const std::string& n : names) valid += (valid.empty() ? "" : ", ") + n;
      throw InputError(option + ": unknown sensor effect '" + name + "' (" + valid + ")");
    }
    settings.on[size_t(it - names.begin())] = on;
  }
}

}  // namespace slamkit::synth
