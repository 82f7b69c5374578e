#pragma once
// Settings given from Python: None (the defaults), a nested dict of some settings, or the path
// of a settings YAML file; read with the checks of `--settings` files (ValueError naming the key).
#include <pybind11/pybind11.h>

#include "core/settings/settings.h"

namespace slamkit::python {

Settings settings_from_python(const pybind11::object& given);

}  // namespace slamkit::python
