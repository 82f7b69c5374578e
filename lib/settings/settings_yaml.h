#pragma once
// Settings files (YAML), sections named as the structs in core/settings/settings.h:
//   orb: {num_features: 1000, ...}  matcher: {...}  tracking: {ransac: {...}, ...}  ...
// A key that is not a setting is an error (a typo would otherwise be silently ignored);
// keys left out keep their defaults.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

#include "core/settings/settings.h"

namespace slamkit {

// Reads over `settings` (which holds the defaults). Throws InputError naming file and line.
void read_settings_yaml(const std::filesystem::path& path, Settings& settings);
// The same for a map of settings inside another YAML file (a suite, a sweep): errors name
// `file` and the line each node has there.
void read_settings_node(const YAML::Node& root, const std::string& file, Settings& settings);

// Whether `dotted_name` ("orb.num_features") names one settings field.
bool is_setting(const std::string& dotted_name);
// Sets one field by its dotted name from a value node of `file`, with every check of the
// reader; an unknown name is an error at `line`.
void apply_setting(const std::string& dotted_name, const YAML::Node& value, const std::string& file,
                   int line, Settings& settings);
void write_settings_yaml(const std::filesystem::path& path, const Settings& settings);
// The text write_settings_yaml writes, byte for byte.
std::string settings_yaml_text(const Settings& settings);

}  // namespace slamkit
