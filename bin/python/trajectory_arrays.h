#pragma once
// Trajectories to and from numpy arrays: stamps (N,), poses (N, 4, 4), positions (N, 3) and
// quaternions (N, 4) in TUM's order qx qy qz qw.
#include <pybind11/numpy.h>

#include <memory>

#include "io/trajectory_io.h"

namespace slamkit::python {

using Array = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;

// A trajectory from arrays, as a file's reader would leave it: sorted by stamp (stably; the file
// is then marked unsorted), quaternions normalised. ValueError naming the argument and row for a
// wrong shape, a non-finite value, a zero quaternion, a repeated stamp or a 4x4 pose that is not
// rigid.
std::shared_ptr<TrajectoryFile> trajectory_from_quaternions(const Array& stamps,
                                                            const Array& positions,
                                                            const Array& quaternions);
std::shared_ptr<TrajectoryFile> trajectory_from_poses(const Array& stamps, const Array& poses);

Array stamps_array(const Trajectory& t);
Array poses_array(const Trajectory& t);
Array positions_array(const Trajectory& t);
Array quaternions_array(const Trajectory& t);

}  // namespace slamkit::python
