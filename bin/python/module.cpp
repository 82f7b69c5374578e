// The slamkit Python module: `import slamkit`. Errors the CLI prints as "slamkit: error: ..."
// (InputError: the file and line at fault) are raised as ValueError with the same text.
#include <pybind11/pybind11.h>

#include "bin/python/bindings.h"
#include "core/error.h"

PYBIND11_MODULE(slamkit, m) {
  m.doc() =
      "slamkit: trajectories, their evaluation (ATE, RPE), RGB-D sequences and runs of the "
      "pipeline, as the slamkit CLI has them";
  pybind11::register_exception<slamkit::InputError>(m, "InputError", PyExc_ValueError);
  slamkit::python::bind_trajectory(m);
  slamkit::python::bind_evaluation(m);
  slamkit::python::bind_sequence(m);
  slamkit::python::bind_settings(m);
  slamkit::python::bind_run(m);
}
