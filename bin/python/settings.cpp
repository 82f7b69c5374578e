// slamkit.settings: the pipeline's settings as a nested dict, read with the checks of
// `--settings` files (lib/settings/settings_yaml.h), so that a bad key or value raises the CLI's
// message. A dict is turned into the YAML text a settings file would hold and read as one.
#include <pybind11/stl/filesystem.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bin/python/bindings.h"
#include "bin/python/settings_from_python.h"
#include "core/error.h"
#include "settings/settings_yaml.h"

namespace slamkit::python {
namespace {

namespace py = pybind11;
using namespace pybind11::literals;

// A dict's value as YAML: sections are maps, numbers in Python's shortest exact form.
YAML::Node to_yaml(const py::handle& value, const std::string& key) {
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& [k, v] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k))
        throw std::invalid_argument("settings: key " + py::repr(k).cast<std::string>() +
                                    (key.empty() ? "" : " in '" + key + "'") + " is not a string");
      const std::string name = k.cast<std::string>();
      map[name] = to_yaml(v, key.empty() ? name : key + "." + name);
    }
    return map;
  }
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
      py::isinstance<py::str>(value))
    return YAML::Node(py::str(value).cast<std::string>());
  throw std::invalid_argument("settings: '" + key + "' holds a " +
                              py::str(value.get_type().attr("__name__")).cast<std::string>() +
                              ", not a number, a string, a bool or a dict of settings");
}

// A value of settings_yaml_text as Python: bool, int, float or str.
py::object scalar(const std::string& text) {
  if (text == "true" || text == "false") return py::bool_(text == "true");
  char* end = nullptr;
  errno = 0;
  const long long whole = std::strtoll(text.c_str(), &end, 10);
  if (!text.empty() && *end == '\0' && errno == 0) return py::int_(whole);
  const double number = std::strtod(text.c_str(), &end);
  if (!text.empty() && *end == '\0') return py::float_(number);
  return py::str(text);
}

py::object to_python(const YAML::Node& node) {
  if (!node.IsMap()) return scalar(node.Scalar());
  py::dict out;
  for (const auto& entry : node) out[py::str(entry.first.Scalar())] = to_python(entry.second);
  return out;
}

}  // namespace

Settings settings_from_python(const py::object& given) {
  Settings settings;
  if (given.is_none()) return settings;
  if (py::isinstance<py::dict>(given)) {
    YAML::Emitter text;
    text << to_yaml(given, "");
    read_settings_node(YAML::Load(text.c_str()), "settings", settings);
  } else {
    read_settings_yaml(given.cast<std::filesystem::path>(), settings);
  }
  return settings;
}

void bind_settings(py::module_& m) {
  m.def(
      "settings",
      [](const py::object& given) {
        return to_python(YAML::Load(settings_yaml_text(settings_from_python(given))));
      },
      "settings"_a = py::none(),
      "Every setting of the pipeline as a nested dict ({'orb': {'num_features': 1000, ...}, "
      "...}): the defaults, over which `settings` (a nested dict of some of them, or the path "
      "of a settings YAML file) is read with the CLI's checks. ValueError naming the key for "
      "an unknown setting or a value out of range.");
  m.def(
      "write_settings",
      [](const py::object& settings, const std::filesystem::path& path) {
        write_settings_yaml(path, settings_from_python(settings));
      },
      "settings"_a, "path"_a,
      "Writes the settings (a dict or a YAML path, as settings() takes) as a complete YAML "
      "file, the text `slamkit settings` prints.");
}

}  // namespace slamkit::python
