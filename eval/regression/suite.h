#pragma once
// A regression suite file (YAML): the sequences to run, their settings, and how far each tracked
// metric may move from its baseline. Read and checked whole before anything runs, so a typo
// costs nothing: bad keys, missing sequences and unknown names are InputErrors naming the
// suite file and line. The format is documented in results/README.md.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/settings/settings.h"

namespace slamkit::regress {

// A metric may get worse by max(abs, rel * |baseline|) before it counts as a regression.
struct Tolerance {
  double abs = 0;
  double rel = 0;
};

struct SequenceSource {
  enum class Kind { kFolder, kTum, kSynthetic };
  Kind kind = Kind::kFolder;
  std::filesystem::path folder;  // kFolder: resolved path; kTum: where it is (or will be)
  std::string tum_name;          // kTum: the download script's name, e.g. freiburg1_desk
  std::string preset;            // kSynthetic
  int frames = 0;
  uint64_t seed = 1;
  std::string sensor = "ideal";  // kSynthetic: `slamkit synth --sensor` (ideal or kinect)
  std::optional<double> depth_scale;
  std::filesystem::path calibration;  // empty: the sequence's own

  // One line for reports: "synthetic desk, 150 frames, seed 1", "TUM freiburg1_desk", ...
  std::string describe() const;
};

// A published figure to print beside the measured one (e.g. ORB-SLAM2's paper table).
struct Reference {
  std::string system;
  double ate_rmse = 0;  // metres
};

struct SuiteEntry {
  std::string name;
  int line = 0;  // of the entry in the suite file
  SequenceSource sequence;
  Settings settings;           // defaults with the suite's and the entry's overrides applied
  bool has_overrides = false;  // false: `slamkit run` gets no --settings
  std::map<std::string, Tolerance> tolerances;  // every tracked metric
  std::optional<Reference> reference;
};

struct Suite {
  std::string name;  // `suite:` or the file's stem; names the baseline folder
  std::filesystem::path file;
  std::string description;
  std::vector<SuiteEntry> entries;
};

// What a suite is checked against; the lists come from the caller so that this module needs
// neither the synthetic generator nor the network.
struct SuiteContext {
  std::optional<std::filesystem::path> data_dir;        // relative folders and TUM downloads
  std::vector<std::string> presets;                     // synthetic preset names
  std::function<std::vector<std::string>()> tum_names;  // asked only if a TUM entry exists
  bool download = true;  // false: a TUM sequence missing from data_dir is an error
};

Suite load_suite(const std::filesystem::path& file, const SuiteContext& context);
// A suite written inside another YAML file (a sweep's `suite:` map), read the same way: errors
// name `file` and the lines there; relative paths are relative to it.
Suite read_suite_node(const YAML::Node& root, const std::filesystem::path& file,
                      const SuiteContext& context);

}  // namespace slamkit::regress
