#pragma once
// One function per part of the module, each in its own file.
#include <pybind11/pybind11.h>

namespace slamkit::python {

void bind_trajectory(pybind11::module_& m);  // trajectory.cpp
void bind_evaluation(pybind11::module_& m);  // evaluation.cpp
void bind_sequence(pybind11::module_& m);    // sequence.cpp
void bind_settings(pybind11::module_& m);    // settings.cpp
void bind_run(pybind11::module_& m);         // run.cpp

}  // namespace slamkit::python
