#pragma once
// Reading and writing whole YAML files with errors that name the file and line.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <string>

namespace slamkit {

// Settings, calibration and suite files are a few kilobytes; yaml-cpp holds a node of about a
// hundred bytes for each few bytes of text, so a larger file is refused before it is parsed.
constexpr uintmax_t kMaxYamlBytes = uintmax_t(1) << 20;

// Throws InputError "path: <what> not found", "path:line: YAML error: ...", or for a file
// larger than kMaxYamlBytes.
YAML::Node load_yaml_file(const std::filesystem::path& path, const std::string& what);

// The text of a plain value (a key or a setting); InputError "path:line: <what> must be a plain
// value, not a map/list/null" otherwise, where yaml-cpp's as<std::string>() would throw its own
// exception type without the file.
std::string scalar_text(const YAML::Node& node, const std::string& path, const std::string& what);

// Writes the emitter's document, creating the folder. Throws InputError when it cannot.
void write_yaml_file(const std::filesystem::path& path, const YAML::Emitter& document);

}  // namespace slamkit
