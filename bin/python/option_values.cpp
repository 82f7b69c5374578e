#include "bin/python/option_values.h"

#include <pybind11/stl.h>

#include <sstream>
#include <stdexcept>

namespace slamkit::python {

namespace py = pybind11;

std::string text(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
}

std::string member(const py::handle& value, const char* option,
                   std::initializer_list<const char*> allowed) {
  const std::string v = text(value);
  std::string list;
  for (const char* a : allowed) {
    if (v == a) return v;
    list += (list.empty() ? "" : ", ") + std::string(a);
  }
  throw std::invalid_argument(std::string(option) + ": '" + v + "' is not one of " + list);
}

std::vector<std::string> plot_formats(const py::handle& value) {
  std::vector<std::string> names;
  if (py::isinstance<py::str>(value)) {
    std::stringstream list(text(value));
    for (std::string name; std::getline(list, name, ',');) names.push_back(name);
  } else {
    names = value.cast<std::vector<std::string>>();
  }
  std::vector<std::string> formats;
  for (const std::string& name : names)
    formats.push_back(member(py::str(name), "plot_format", {"png", "svg", "pdf"}));
  return formats;
}

int dpi(const py::handle& value) {
  const int dots = value.cast<int>();
  if (dots < 10 || dots > 2400)
    throw std::invalid_argument("dpi: " + std::to_string(dots) + " not in [10, 2400]");
  return dots;
}

}  // namespace slamkit::python
