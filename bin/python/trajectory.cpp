// slamkit.Trajectory and its files: read_trajectory() reads TUM, KITTI and EuRoC files with the
// readers of `slamkit eval`, Trajectory.write() writes TUM files as `slamkit` does (aligned.txt,
// trajectory.txt).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bin/python/bindings.h"
#include "io/euroc_csv.h"
#include "io/kitti_poses.h"
#include "io/trajectory_format.h"
#include "bin/python/trajectory_arrays.h"

namespace slamkit::python {

namespace py = pybind11;
using namespace pybind11::literals;

void bind_trajectory(py::module_& m) {
  py::class_<TrajectoryFile, std::shared_ptr<TrajectoryFile>>(
      m, "Trajectory",
      "Camera poses T_w_c with timestamps in seconds, sorted by time. Build one from arrays or "
      "read one with read_trajectory().")
      .def(py::init([](const Array& stamps, const std::optional<Array>& poses,
                       const std::optional<Array>& positions,
                       const std::optional<Array>& quaternions) {
             if (poses && !positions && !quaternions) return trajectory_from_poses(stamps, *poses);
             if (!poses && positions && quaternions)
               return trajectory_from_quaternions(stamps, *positions, *quaternions);
             throw std::invalid_argument(
                 "give either poses (N, 4, 4) or both positions (N, 3) and quaternions (N, 4)");
           }),
           "stamps"_a, "poses"_a = py::none(), py::kw_only(), "positions"_a = py::none(),
           "quaternions"_a = py::none(),
           "Trajectory(stamps, poses) with poses (N, 4, 4), or Trajectory(stamps, positions=, "
           "quaternions=) with quaternions (N, 4) as qx qy qz qw (TUM's order). Sorted by stamp; "
           "quaternions normalised; a repeated stamp raises ValueError.")
      .def("__len__", [](const TrajectoryFile& f) { return f.trajectory.size(); })
      .def_property_readonly("stamps",
                             [](const TrajectoryFile& f) { return stamps_array(f.trajectory); })
      .def_property_readonly(
          "poses", [](const TrajectoryFile& f) { return poses_array(f.trajectory); },
          "(N, 4, 4) T_w_c")
      .def_property_readonly("positions",
                             [](const TrajectoryFile& f) { return positions_array(f.trajectory); })
      .def_property_readonly(
          "quaternions", [](const TrajectoryFile& f) { return quaternions_array(f.trajectory); },
          "(N, 4) qx qy qz qw")
      .def_readonly("warnings", &TrajectoryFile::warnings,
                    "What the reader skipped or changed, one line each (naming file and line)")
      .def_readonly("was_unsorted", &TrajectoryFile::was_unsorted)
      .def(
          "write",
          [](const TrajectoryFile& f, const std::filesystem::path& path, const std::string& comment,
             const std::string& format, const std::optional<std::filesystem::path>& times) {
            const TrajectoryFormat chosen = parse_trajectory_format(format);
            if (chosen != TrajectoryFormat::kTum && !comment.empty())
              throw std::invalid_argument("comment: only a TUM file holds one");
            if (chosen != TrajectoryFormat::kKitti && times)
              throw std::invalid_argument("times: only a KITTI pose file has a times file");
            py::gil_scoped_release release;
            if (chosen == TrajectoryFormat::kTum) write_tum_trajectory(path, f.trajectory, comment);
            if (chosen == TrajectoryFormat::kKitti) write_kitti_poses(path, f.trajectory, times);
            if (chosen == TrajectoryFormat::kEuroc) write_euroc_csv(path, f.trajectory);
          },
          "path"_a, "comment"_a = "", py::kw_only(), "format"_a = "tum", "times"_a = py::none(),
          "Writes the trajectory as read_trajectory reads it back: 'tum' as slamkit does (every "
          "number in its shortest exact form, '# comment' first when given), 'kitti' (the 3x4 "
          "[R|t] rows; times= also writes the stamps as a times.txt), 'euroc' (ASL CSV, stamps "
          "rounded to the nanosecond).")
      .def("__repr__", [](const TrajectoryFile& f) {
        const Trajectory& t = f.trajectory;
        return "<slamkit.Trajectory " + std::to_string(t.size()) + " poses>";
      });

  m.def(
      "read_trajectory",
      [](const std::filesystem::path& path, const std::optional<std::string>& format,
         const std::optional<std::filesystem::path>& times, const std::string& time_unit,
         const std::string& duplicate_stamps) {
        TrajectoryReadOptions options;
        options.time_unit = parse_time_unit(time_unit);
        options.duplicates = parse_duplicate_stamps(duplicate_stamps);
        const std::optional<TrajectoryFormat> chosen =
            format ? std::optional(parse_trajectory_format(*format)) : std::nullopt;
        py::gil_scoped_release release;
        return std::make_shared<TrajectoryFile>(read_trajectory(path, chosen, options, times));
      },
      "path"_a, py::kw_only(), "format"_a = py::none(), "times"_a = py::none(),
      "time_unit"_a = "s", "duplicate_stamps"_a = "last",
      "Reads a trajectory as `slamkit eval` does: format 'tum', 'kitti' or 'euroc' (None: "
      "detected from the content), times= a KITTI times.txt; ValueError naming file and line "
      "for what the CLI refuses.");
}

}  // namespace slamkit::python
