#pragma once
// Reading values out of a hand-written YAML file (a suite, a sweep) with errors that name the
// file and the line of the node at fault, as InputError.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>

namespace slamkit::regress {

class YamlChecks {
 public:
  explicit YamlChecks(std::string path) : path_(std::move(path)) {}

  const std::string& path() const { return path_; }

  // Every key of `map` is one of `allowed`.
  void check_keys(const YAML::Node& map, std::initializer_list<const char*> allowed) const;
  // Names become folder and file names: letters, digits, '_', '-' and '.'.
  void check_name(const YAML::Node& at, const std::string& name, const std::string& what) const;
  std::string scalar(const YAML::Node& node, const std::string& what) const;
  double number(const YAML::Node& node, const std::string& what) const;
  double non_negative(const YAML::Node& node, const std::string& what) const;
  long long integer(const YAML::Node& node, const std::string& what) const;

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const;

 private:
  std::string path_;
};

// Whether a name can be a folder name as check_name requires.
bool is_plain_name(const std::string& name);

}  // namespace slamkit::regress
