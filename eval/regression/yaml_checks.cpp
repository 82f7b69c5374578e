#include "eval/regression/yaml_checks.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "io/yaml_file.h"

namespace slamkit::regress {

bool is_plain_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

void YamlChecks::check_keys(const YAML::Node& map,
                            std::initializer_list<const char*> allowed) const {
  for (const auto& kv : map) {
    const std::string key = scalar_text(kv.first, path_, "a key");
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return key == a; })) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      fail(kv.first, "unknown key '" + key + "' (expected " + list + ")");
    }
  }
}

void YamlChecks::check_name(const YAML::Node& at, const std::string& name,
                            const std::string& what) const {
  if (!is_plain_name(name))
    fail(at, what + " '" + name + "' may hold only letters, digits, '_', '-' and '.'");
}

std::string YamlChecks::scalar(const YAML::Node& node, const std::string& what) const {
  if (!node.IsScalar() || node.Scalar().empty()) fail(node, what + " must be a non-empty value");
  return node.Scalar();
}

double YamlChecks::number(const YAML::Node& node, const std::string& what) const {
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    fail(node, what + " must be a number");
  }
}

double YamlChecks::non_negative(const YAML::Node& node, const std::string& what) const {
  const double v = number(node, what);
  if (!(v >= 0)) fail(node, what + " must be zero or positive");
  return v;
}

long long YamlChecks::integer(const YAML::Node& node, const std::string& what) const {
  try {
    return node.as<long long>();
  } catch (const YAML::Exception&) {
    fail(node, what + " must be an integer");
  }
}

void YamlChecks::fail(const YAML::Node& at, const std::string& message) const {
  throw_input_error(path_, at.Mark().line + 1, message);
}

}  // namespace slamkit::regress
