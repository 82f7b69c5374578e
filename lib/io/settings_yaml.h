#pragma once
// Settings files (YAML), sections named as the structs in core/settings/settings.h:
//   orb: {num_features: 1000, ...}  matcher: {...}  tracking: {ransac: {...}, ...}  ...
// A key that is not a setting is an error (a typo would otherwise be silently ignored);
// keys left out keep their defaults.
#include <filesystem>
#include <string>

#include "core/settings/settings.h"

namespace slamkit {

// Reads over `settings` (which holds the defaults). Throws InputError naming file and line.
void read_settings_yaml(const std::filesystem::path& path, Settings& settings);
void write_settings_yaml(const std::filesystem::path& path, const Settings& settings);
// The text write_settings_yaml writes, byte for byte.
std::string settings_yaml_text(const Settings& settings);

}  // namespace slamkit
