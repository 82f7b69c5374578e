#pragma once
// A sweep file (YAML): a regression suite (a suite file, or one written inline) times a grid of
// settings times seeds, and the metrics to rank the variants by. Read and checked whole before
// anything runs, like a suite: every error is an InputError naming the sweep file and line.
// The format is documented in README.md ("Sweeps on a cluster").
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "eval/regression/suite.h"

namespace slamkit::sweep {

// One settings key set by a variant, as written in the sweep file.
struct SettingOverride {
  std::string key;   // dotted: orb.num_features
  YAML::Node value;  // keeps its line, so the settings reader's errors name it
  int line = 0;      // of the key
};

struct Variant {
  std::string name;  // a folder name: named in the file, or made from the grid's values
  std::vector<SettingOverride> overrides;
};

struct Sweep {
  std::string name;
  std::filesystem::path file;
  std::string description;
  regress::Suite suite;
  std::vector<Variant> variants;     // the grid's cross product or the named list, in file order
  std::vector<uint64_t> seeds;       // empty: every run keeps the suite's own seeds
  std::vector<std::string> rank_by;  // tracked metric keys
};

// What a seed sets besides the seed of a synthetic sequence (its hand shake and noise): the
// random seed of the pipeline, so real sequences vary from seed to seed too.
inline const char* kSeedSetting = "tracking.ransac.seed";

Sweep load_sweep(const std::filesystem::path& file, const regress::SuiteContext& context);

// The entry's settings with the variant's overrides and the seed applied (the seed to the
// synthetic sequence as well). Checked when the sweep was loaded, so it does not fail then.
regress::SuiteEntry variant_entry(const Sweep& sweep, const regress::SuiteEntry& entry,
                                  const Variant& variant, const uint64_t* seed);

}  // namespace slamkit::sweep
