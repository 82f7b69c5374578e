#pragma once
// Keyword options' values, checked as the CLI checks its options' values (evaluation.cpp,
// run.cpp).
#include <pybind11/pybind11.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace slamkit::python {

// A str, or an os.PathLike as its path.
std::string text(const pybind11::handle& value);

// `value` as text when it is one of `allowed`, else std::invalid_argument naming `option`.
std::string member(const pybind11::handle& value, const char* option,
                   std::initializer_list<const char*> allowed);

// plot_format=: "png,svg" or a list of names, as --plot-format given once or repeated.
std::vector<std::string> plot_formats(const pybind11::handle& value);

// dpi=: in [10, 2400], as --dpi.
int dpi(const pybind11::handle& value);

}  // namespace slamkit::python
