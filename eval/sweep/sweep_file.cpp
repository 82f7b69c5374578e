#include "eval/sweep/sweep_file.h"

#include <algorithm>
#include <set>

#include "core/error.h"
#include "eval/regression/metrics.h"
#include "eval/regression/yaml_checks.h"
#include "io/path_kind.h"
#include "settings/settings_yaml.h"
#include "io/yaml_file.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;
using regress::SuiteContext;

// The part of a settings key that names it in a variant's name: the last one, unless two keys
// of the grid share it.
std::vector<std::string> short_labels(const std::vector<std::string>& keys) {
  std::vector<std::string> labels;
  for (const std::string& key : keys) labels.push_back(key.substr(key.rfind('.') + 1));
  for (size_t i = 0; i < keys.size(); ++i)
    for (size_t j = 0; j < keys.size(); ++j)
      if (i != j && labels[i] == keys[j].substr(keys[j].rfind('.') + 1)) labels[i] = keys[i];
  return labels;
}

// A value as it may stand in a folder name.
std::string name_part(const std::string& value) {
  std::string out = value;
  for (char& c : out)
    if (!regress::is_plain_name(std::string(1, c))) c = '_';
  return out;
}

class SweepReader : regress::YamlChecks {
 public:
  SweepReader(const fs::path& file, const SuiteContext& context)
      : YamlChecks(file.string()), file_(file), context_(context) {}

  Sweep read(const YAML::Node& root) {
    if (!root.IsMap()) fail(root, "expected a map with 'suite' and 'grid' or 'variants'");
    check_keys(root, {"sweep", "description", "suite", "grid", "variants", "seeds", "rank_by"});
    Sweep sweep;
    sweep.file = file_;
    sweep.name = root["sweep"] ? scalar(root["sweep"], "sweep") : file_.stem().string();
    check_name(root["sweep"] ? root["sweep"] : root, sweep.name, "sweep name");
    if (root["description"]) sweep.description = scalar(root["description"], "description");
    if (!root["suite"]) fail(root, "no 'suite': a suite file, or a map with 'entries'");
    sweep.suite = read_suite(root["suite"]);
    if (root["grid"] && root["variants"])
      fail(root["variants"], "give 'grid' or 'variants', not both");
    if (root["grid"])
      sweep.variants = read_grid(root["grid"]);
    else if (root["variants"])
      sweep.variants = read_variants(root["variants"]);
    else
      sweep.variants = {Variant{"defaults", {}}};
    if (root["seeds"]) sweep.seeds = read_seeds(root["seeds"]);
    sweep.rank_by =
        root["rank_by"] ? read_metrics(root["rank_by"]) : std::vector<std::string>{"ate_rmse"};
    for (const Variant& v : sweep.variants) check_variant(v, !sweep.seeds.empty());
    return sweep;
  }

 private:
  regress::Suite read_suite(const YAML::Node& node) {
    if (node.IsScalar()) {
      fs::path suite = scalar(node, "suite");
      if (suite.is_relative()) suite = file_.parent_path() / suite;
      if (path_kind(suite) != PathKind::kFile)
        fail(node, "suite file '" + suite.string() + "' not found");
      return regress::load_suite(suite, context_);
    }
    if (!node.IsMap()) fail(node, "suite must be a suite file or a map with 'entries'");
    return regress::read_suite_node(node, file_, context_);
  }

  // key: [values...] for each key; the cross product, the first key varying slowest.
  std::vector<Variant> read_grid(const YAML::Node& grid) {
    if (!grid.IsMap() || grid.size() == 0)
      fail(grid, "grid must be a map of settings keys to lists of values");
    std::vector<std::string> keys;
    std::vector<YAML::Node> key_nodes, lists;
    for (const auto& kv : grid) {
      keys.push_back(scalar(kv.first, "grid key"));
      if (!is_setting(keys.back())) fail(kv.first, "unknown setting '" + keys.back() + "'");
      if (!kv.second.IsSequence() || kv.second.size() == 0)
        fail(kv.second, keys.back() + " needs a non-empty list of values");
      for (const YAML::Node& value : kv.second)
        if (!value.IsScalar()) fail(value, keys.back() + ": each value must be a single value");
      key_nodes.push_back(kv.first);
      lists.push_back(kv.second);
    }
    const std::vector<std::string> labels = short_labels(keys);
    std::vector<Variant> variants = {Variant{}};
    for (size_t k = 0; k < keys.size(); ++k) {
      std::vector<Variant> grown;
      for (const Variant& base : variants)
        for (const YAML::Node& value : lists[k]) {
          Variant v = base;
          v.name += (v.name.empty() ? "" : "_") + labels[k] + "-" + name_part(value.Scalar());
          v.overrides.push_back({keys[k], value, key_nodes[k].Mark().line + 1});
          grown.push_back(std::move(v));
        }
      variants = std::move(grown);
    }
    std::set<std::string> names;
    for (const Variant& v : variants)
      if (!names.insert(v.name).second)
        fail(grid, "two grid points are both named '" + v.name + "': make the values differ");
    return variants;
  }

  // - name: N
  //   settings: {orb: {num_features: 500}}   (nested, or dotted keys)
  std::vector<Variant> read_variants(const YAML::Node& list) {
    if (!list.IsSequence() || list.size() == 0)
      fail(list, "variants must be a non-empty list of {name, settings}");
    std::vector<Variant> variants;
    std::set<std::string> names;
    for (const YAML::Node& node : list) {
      if (!node.IsMap()) fail(node, "a variant must be a map {name, settings}");
      check_keys(node, {"name", "settings"});
      if (!node["name"]) fail(node, "variant without a 'name'");
      Variant v;
      v.name = scalar(node["name"], "variant name");
      check_name(node["name"], v.name, "variant name");
      if (!names.insert(v.name).second)
        fail(node["name"], "variant name '" + v.name + "' is used twice");
      if (const YAML::Node settings = node["settings"]) {
        if (!settings.IsMap()) fail(settings, "settings of a variant must be a map of settings");
        flatten(settings, "", v.overrides);
      }
      variants.push_back(std::move(v));
    }
    return variants;
  }

  void flatten(const YAML::Node& map, const std::string& prefix,
               std::vector<SettingOverride>& out) const {
    for (const auto& kv : map) {
      const std::string key = prefix + scalar(kv.first, "settings key");
      if (kv.second.IsMap())
        flatten(kv.second, key + ".", out);
      else
        out.push_back({key, kv.second, kv.first.Mark().line + 1});
    }
  }

  std::vector<uint64_t> read_seeds(const YAML::Node& node) {
    if (!node.IsSequence() || node.size() == 0)
      fail(node, "seeds must be a non-empty list of integers");
    std::vector<uint64_t> seeds;
    for (const YAML::Node& s : node) {
      const long long seed = integer(s, "a seed");
      // The pipeline's seed is 32 bits wide.
      if (seed < 0 || seed > 0xffffffffLL) fail(s, "a seed must lie in 0..4294967295");
      if (std::find(seeds.begin(), seeds.end(), uint64_t(seed)) != seeds.end())
        fail(s, "seed " + std::to_string(seed) + " is listed twice");
      seeds.push_back(uint64_t(seed));
    }
    return seeds;
  }

  std::vector<std::string> read_metrics(const YAML::Node& node) {
    if (!node.IsSequence() || node.size() == 0)
      fail(node, "rank_by must be a non-empty list of metrics");
    std::vector<std::string> keys;
    for (const YAML::Node& m : node) {
      const std::string key = scalar(m, "a metric");
      if (!regress::find_metric(key)) {
        std::string list;
        for (const regress::MetricInfo& known : regress::tracked_metrics())
          list += (list.empty() ? "" : ", ") + known.key;
        fail(m, "unknown metric '" + key + "' (" + list + ")");
      }
      keys.push_back(key);
    }
    return keys;
  }

  // Every override through the settings reader (unknown keys, types, ranges), once, at its line.
  void check_variant(const Variant& v, bool seeded) const {
    Settings settings;
    for (const SettingOverride& o : v.overrides) {
      if (seeded && o.key == kSeedSetting)
        throw_input_error(path(), o.line,
                          o.key + " is what the sweep's seeds set: drop it here or drop seeds");
      apply_setting(o.key, o.value, path(), o.line, settings);
    }
  }

  fs::path file_;
  const SuiteContext& context_;
};

}  // namespace

Sweep load_sweep(const fs::path& file, const SuiteContext& context) {
  return SweepReader(file, context).read(load_yaml_file(file, "sweep file"));
}

regress::SuiteEntry variant_entry(const Sweep& sweep, const regress::SuiteEntry& entry,
                                  const Variant& variant, const uint64_t* seed) {
  regress::SuiteEntry out = entry;
  for (const SettingOverride& o : variant.overrides)
    apply_setting(o.key, o.value, sweep.file.string(), o.line, out.settings);
  if (seed) {
    out.settings.tracking.ransac.seed = uint32_t(*seed);
    if (out.sequence.kind == regress::SequenceSource::Kind::kSynthetic) out.sequence.seed = *seed;
  }
  out.has_overrides = entry.has_overrides || !variant.overrides.empty() || seed;
  return out;
}

}  // namespace slamkit::sweep
