#include "eval/regression/suite.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "core/error.h"
#include "eval/regression/metrics.h"
#include "eval/regression/yaml_checks.h"
#include "io/path_kind.h"
#include "settings/settings_yaml.h"
#include "io/tum_sequence.h"
#include "io/yaml_file.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

class SuiteReader : YamlChecks {
 public:
  SuiteReader(const fs::path& file, const SuiteContext& context)
      : YamlChecks(file.string()), dir_(file.parent_path()), context_(context) {}

  Suite read(const YAML::Node& root) {
    Suite suite;
    suite.file = path();
    if (!root.IsMap()) fail(root, "expected a map with 'entries'");
    check_keys(root, {"suite", "description", "settings", "tolerances", "entries"});
    suite.name = root["suite"] ? scalar(root["suite"], "suite") : fs::path(path()).stem().string();
    check_name(root["suite"] ? root["suite"] : root, suite.name, "suite name");
    if (root["description"]) suite.description = scalar(root["description"], "description");

    std::map<std::string, Tolerance> tolerances;
    for (const MetricInfo& m : tracked_metrics()) tolerances[m.key] = m.tolerance;
    if (root["tolerances"]) read_tolerances(root["tolerances"], tolerances);
    Settings settings;
    const bool suite_overrides = root["settings"] && apply_settings(root["settings"], settings);

    const YAML::Node entries = root["entries"];
    if (!entries) fail(root, "no 'entries' list");
    if (!entries.IsSequence() || entries.size() == 0)
      fail(entries, "'entries' must be a non-empty list");
    std::set<std::string> names;
    for (const YAML::Node& node : entries) {
      SuiteEntry entry = read_entry(node, settings, tolerances);
      entry.has_overrides = entry.has_overrides || suite_overrides;
      if (!names.insert(entry.name).second)
        fail(node["name"], "entry name '" + entry.name + "' is used twice");
      suite.entries.push_back(std::move(entry));
    }
    return suite;
  }

 private:
  SuiteEntry read_entry(const YAML::Node& node, const Settings& suite_settings,
                        const std::map<std::string, Tolerance>& suite_tolerances) {
    if (!node.IsMap()) fail(node, "an entry must be a map with a name and a sequence");
    check_keys(node, {"name", "folder", "tum", "synthetic", "depth_scale", "calibration",
                      "settings", "tolerances", "reference"});
    SuiteEntry entry;
    entry.line = node.Mark().line + 1;
    if (!node["name"]) fail(node, "entry without a 'name'");
    entry.name = scalar(node["name"], "name");
    check_name(node["name"], entry.name, "entry name");
    entry.sequence = read_sequence(node);
    entry.settings = suite_settings;
    if (node["settings"]) entry.has_overrides = apply_settings(node["settings"], entry.settings);
    entry.tolerances = suite_tolerances;
    if (node["tolerances"]) read_tolerances(node["tolerances"], entry.tolerances);
    if (const YAML::Node ref = node["reference"]) {
      if (!ref.IsMap()) fail(ref, "reference must be a map {system, ate_rmse}");
      check_keys(ref, {"system", "ate_rmse"});
      if (!ref["system"] || !ref["ate_rmse"]) fail(ref, "reference needs system and ate_rmse");
      entry.reference = Reference{scalar(ref["system"], "reference.system"),
                                  number(ref["ate_rmse"], "reference.ate_rmse")};
    }
    return entry;
  }

  SequenceSource read_sequence(const YAML::Node& node) {
    const int kinds = bool(node["folder"]) + bool(node["tum"]) + bool(node["synthetic"]);
    if (kinds != 1) fail(node, "an entry needs exactly one of folder, tum and synthetic");
    SequenceSource s;
    if (const YAML::Node folder = node["folder"]) {
      s.kind = SequenceSource::Kind::kFolder;
      fs::path path = scalar(folder, "folder");
      if (path.is_relative()) {
        if (!context_.data_dir)
          fail(folder, "relative folder '" + path.string() +
                           "' needs the data folder: set SLAMKIT_DATA or pass --data");
        path = *context_.data_dir / path;
      }
      if (path_kind(path) != PathKind::kFolder)
        fail(folder, "sequence folder '" + path.string() + "' not found");
      s.folder = path;
    } else if (const YAML::Node tum = node["tum"]) {
      s.kind = SequenceSource::Kind::kTum;
      s.tum_name = scalar(tum, "tum");
      const std::vector<std::string> known = context_.tum_names();
      if (std::find(known.begin(), known.end(), s.tum_name) == known.end())
        fail(tum, "unknown TUM RGB-D sequence '" + s.tum_name +
                      "' (datasets/download_tum.sh --list shows the names)");
      if (!context_.data_dir)
        fail(tum, "TUM sequences are kept in the data folder: set SLAMKIT_DATA or pass --data");
      s.folder = *context_.data_dir / ("rgbd_dataset_" + s.tum_name);
      if (!context_.download && path_kind(s.folder / "groundtruth.txt") == PathKind::kMissing)
        fail(tum, "'" + s.folder.string() + "' not found (downloads are off)");
    } else {
      const YAML::Node synth = node["synthetic"];
      s.kind = SequenceSource::Kind::kSynthetic;
      if (!synth.IsMap()) fail(synth, "synthetic must be a map {preset, frames, seed, sensor}");
      check_keys(synth, {"preset", "frames", "seed", "sensor"});
      if (!synth["preset"] || !synth["frames"]) fail(synth, "synthetic needs preset and frames");
      s.preset = scalar(synth["preset"], "preset");
      const auto& presets = context_.presets;
      if (std::find(presets.begin(), presets.end(), s.preset) == presets.end()) {
        std::string list;
        for (const std::string& p : presets) list += (list.empty() ? "" : ", ") + p;
        fail(synth["preset"], "unknown synthetic preset '" + s.preset + "' (" + list + ")");
      }
      s.frames = integer(synth["frames"], "frames");
      if (s.frames < 2) fail(synth["frames"], "frames must be at least 2");
      if (synth["seed"]) s.seed = uint64_t(integer(synth["seed"], "seed"));
      if (synth["sensor"]) {
        s.sensor = scalar(synth["sensor"], "sensor");
        if (s.sensor != "ideal" && s.sensor != "kinect")
          fail(synth["sensor"], "unknown sensor '" + s.sensor + "' (ideal or kinect)");
      }
    }
    if (node["depth_scale"]) {
      s.depth_scale = number(node["depth_scale"], "depth_scale");
      if (*s.depth_scale <= 0) fail(node["depth_scale"], "depth_scale must be positive");
    }
    if (const YAML::Node calibration = node["calibration"]) {
      s.calibration = relative_to_suite(scalar(calibration, "calibration"));
      if (path_kind(s.calibration) != PathKind::kFile)
        fail(calibration, "calibration file '" + s.calibration.string() + "' not found");
    }
    if (s.kind == SequenceSource::Kind::kFolder) {
      // Its lists, camera and groundtruth are checked now too (the images only when it runs), so
      // that a broken sequence is bad input (exit 2) before anything runs.
      SequenceOptions options;
      if (!s.calibration.empty()) options.calibration_file = s.calibration;
      options.depth_scale = s.depth_scale;
      TumSequence::open(s.folder, options);
    }
    return s;
  }

  // `settings:` is a settings file (relative to the suite) or a map of inline keys; both are
  // read by the settings reader itself, so its checks (unknown keys, types, ranges) apply
  // unchanged, inline ones at the suite's lines.
  bool apply_settings(const YAML::Node& node, Settings& settings) {
    if (node.IsScalar()) {
      const fs::path file = relative_to_suite(node.Scalar());
      if (path_kind(file) != PathKind::kFile)
        fail(node, "settings file '" + file.string() + "' not found");
      read_settings_yaml(file, settings);
      return true;
    }
    if (!node.IsMap()) fail(node, "settings must be a file name or a map of settings");
    read_settings_node(node, path(), settings);
    return true;
  }

  void read_tolerances(const YAML::Node& node, std::map<std::string, Tolerance>& tolerances) {
    if (!node.IsMap()) fail(node, "tolerances must be a map: metric: {abs: A, rel: R}");
    for (const auto& kv : node) {
      const std::string key = scalar_text(kv.first, path(), "a metric name");
      if (!find_metric(key)) {
        std::string list;
        for (const MetricInfo& m : tracked_metrics()) list += (list.empty() ? "" : ", ") + m.key;
        fail(kv.first, "unknown metric '" + key + "' (" + list + ")");
      }
      if (!kv.second.IsMap()) fail(kv.second, "tolerance of " + key + " must be {abs, rel}");
      check_keys(kv.second, {"abs", "rel"});
      Tolerance& t = tolerances[key];
      if (kv.second["abs"]) t.abs = non_negative(kv.second["abs"], key + ".abs");
      if (kv.second["rel"]) t.rel = non_negative(kv.second["rel"], key + ".rel");
    }
  }

  fs::path relative_to_suite(const fs::path& path) const {
    return path.is_relative() ? dir_ / path : path;
  }

  fs::path dir_;
  const SuiteContext& context_;
};

}  // namespace

std::string SequenceSource::describe() const {
  std::string text;
  switch (kind) {
    case Kind::kFolder:
      text = folder.filename().string();
      break;
    case Kind::kTum:
      text = "TUM " + tum_name;
      break;
    case Kind::kSynthetic:
      text = "synthetic " + preset + ", " + std::to_string(frames) + " frames, seed " +
             std::to_string(seed) + (sensor == "ideal" ? "" : ", " + sensor + " sensor");
      break;
  }
  if (depth_scale) {
    char scale[32];
    std::snprintf(scale, sizeof scale, "%g", *depth_scale);
    text += std::string(", depth scale ") + scale;
  }
  if (!calibration.empty()) text += ", calibration " + calibration.filename().string();
  return text;
}

Suite load_suite(const fs::path& file, const SuiteContext& context) {
  return read_suite_node(load_yaml_file(file, "suite file"), file, context);
}

Suite read_suite_node(const YAML::Node& root, const fs::path& file, const SuiteContext& context) {
  return SuiteReader(file, context).read(root);
}

}  // namespace slamkit::regress
