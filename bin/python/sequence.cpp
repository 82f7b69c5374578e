// slamkit.Sequence (a TUM RGB-D folder, read as `slamkit run` reads it) and slamkit.synth
// (`slamkit synth`: renders a synthetic sequence into a folder).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <opencv2/imgproc.hpp>

#include "bin/output_folder.h"
#include "bin/python/bindings.h"
#include "bin/python/trajectory_arrays.h"
#include "datasets/synth/room_layout.h"
#include "datasets/synth/sensor_choice.h"
#include "datasets/synth/sequence_writer.h"
#include "io/tum_sequence.h"

namespace slamkit::python {
namespace {

namespace py = pybind11;
using namespace pybind11::literals;

// A copy of a decoded image as a numpy array (rows, columns[, channels]).
template <class T>
py::array_t<T> image_array(const cv::Mat& image) {
  std::vector<py::ssize_t> shape = {image.rows, image.cols};
  if (image.channels() > 1) shape.push_back(image.channels());
  py::array_t<T> out(shape);
  const size_t row_bytes = size_t(image.cols) * image.elemSize();
  for (int r = 0; r < image.rows; ++r)
    std::memcpy(out.mutable_data() + size_t(r) * image.cols * image.channels(), image.ptr(r),
                row_bytes);
  return out;
}

py::object load_frame(const TumSequence& sequence, py::ssize_t i) {
  const auto n = static_cast<py::ssize_t>(sequence.size());
  if (i < 0) i += n;
  if (i < 0 || i >= n)
    throw py::index_error("frame " + std::to_string(i) + " of a sequence of " + std::to_string(n));
  RgbdFrame frame;
  cv::Mat rgb;
  {
    py::gil_scoped_release release;
    frame = sequence.load(size_t(i));
    cv::cvtColor(frame.rgb, rgb, cv::COLOR_BGR2RGB);  // numpy's and matplotlib's order
  }
  return py::module_::import("types").attr("SimpleNamespace")(
      "index"_a = frame.index, "stamp"_a = frame.stamp,
      "depth_stamp"_a = sequence.depth_stamp(size_t(i)), "colour"_a = image_array<uint8_t>(rgb),
      "depth"_a = image_array<float>(frame.depth));
}

py::dict camera_dict(const Camera& c) {
  return py::dict("name"_a = c.name, "fx"_a = c.fx, "fy"_a = c.fy, "cx"_a = c.cx, "cy"_a = c.cy,
                  "width"_a = c.width, "height"_a = c.height, "depth_scale"_a = c.depth_scale,
                  "min_depth"_a = c.min_depth, "max_depth"_a = c.max_depth,
                  "distortion"_a = py::make_tuple(c.distortion.k1, c.distortion.k2, c.distortion.p1,
                                                  c.distortion.p2, c.distortion.k3),
                  "readout_time"_a = c.readout_time);
}

// Rendering calls `progress` on its first thread while the others render, so an exception
// cannot leave the callback: the first one (a KeyboardInterrupt included) is kept, the
// callback is not called again, and it is raised once rendering has ended.
struct ProgressRelay {
  py::object callback;
  std::optional<py::error_already_set> error;

  void operator()(size_t done) {
    py::gil_scoped_acquire acquire;
    if (error) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!callback.is_none()) callback(done);
    } catch (py::error_already_set& e) {
      error = std::move(e);
    }
  }
};

}  // namespace

void bind_sequence(py::module_& m) {
  py::class_<TumSequence>(m, "Sequence",
                          "A TUM RGB-D sequence folder (rgb/, depth/, rgb.txt, depth.txt, "
                          "[groundtruth.txt]) as `slamkit run` reads it; frames decoded on access.")
      .def(py::init([](const std::filesystem::path& folder, double max_time_diff,
                       double time_offset, const std::optional<std::filesystem::path>& association,
                       const std::optional<std::filesystem::path>& calibration,
                       std::optional<double> depth_scale) {
             SequenceOptions options;
             options.max_time_diff = max_time_diff;
             options.time_offset = time_offset;
             options.association_file = association;
             options.calibration_file = calibration;
             options.depth_scale = depth_scale;
             py::gil_scoped_release release;
             return TumSequence::open(folder, options);
           }),
           "folder"_a, py::kw_only(), "max_time_diff"_a = 0.02, "time_offset"_a = 0.0,
           "association"_a = py::none(), "calibration"_a = py::none(), "depth_scale"_a = py::none(),
           "Opens a folder; options as `slamkit run`'s --max-time-diff, --time-offset, "
           "--association, --calibration, --depth-scale. ValueError naming file and line.")
      .def("__len__", &TumSequence::size)
      .def("__getitem__", &load_frame, "i"_a,
           "Frame i: .index, .stamp, .depth_stamp, .colour (H, W, 3) uint8 RGB, .depth (H, W) "
           "float32 metres (0 where invalid)")
      .def("__iter__",
           [](const py::object& self) {
             return py::module_::import("builtins")
                 .attr("map")(self.attr("__getitem__"),
                              py::module_::import("builtins").attr("range")(py::len(self)));
           })
      .def_property_readonly("folder", &TumSequence::folder)
      .def_property_readonly("stamps",
                             [](const TumSequence& s) {
                               std::vector<double> stamps(s.size());
                               for (size_t i = 0; i < s.size(); ++i) stamps[i] = s.stamp(i);
                               return py::array_t<double>(py::ssize_t(stamps.size()),
                                                          stamps.data());
                             })
      .def_property_readonly("camera", [](const TumSequence& s) { return camera_dict(s.camera()); })
      .def_property_readonly("groundtruth", [](const TumSequence& s) -> py::object {
        if (!s.groundtruth()) return py::none();
        auto file = std::make_shared<TrajectoryFile>();
        file->trajectory = *s.groundtruth();
        return py::cast(file);
      });

  m.def(
      "synth",
      [](const std::string& preset, int frames, uint64_t seed, const std::string& sensor,
         const std::filesystem::path& out, int threads, const std::string& sensor_settings,
         const std::string& sensor_off, const std::string& sensor_on, const py::object& progress) {
        cli::check_output_folder("--out", out);
        synth::SequenceSpec spec;
        spec.preset = synth::parse_preset(preset);
        spec.frames = frames;
        spec.seed = seed;
        spec.threads = threads;
        spec.out = out;
        spec.kinect = synth::kinect_settings({sensor, sensor_settings, sensor_off, sensor_on});
        synth::check_spec(spec);
        ProgressRelay relay{progress, std::nullopt};
        {
          py::gil_scoped_release release;
          const synth::SyntheticScene scene =
              synth::make_named_scene(synth::preset_scene(spec.preset));
          synth::write_sequence(scene, spec, std::ref(relay));
        }
        if (relay.error) throw std::move(*relay.error);
        py::gil_scoped_release release;
        return TumSequence::open(out);
      },
      "preset"_a = "desk", "frames"_a = 600, "seed"_a = 1, "sensor"_a = "ideal", py::kw_only(),
      "out"_a, "threads"_a = 0, "sensor_settings"_a = "", "sensor_off"_a = "", "sensor_on"_a = "",
      "progress"_a = py::none(),
      "`slamkit synth`: renders a synthetic sequence into `out` (the same files, byte for byte) "
      "and opens it. progress(frames_done) is called now and then; an exception it raises, or "
      "Ctrl-C, is raised when rendering has ended.");
}

}  // namespace slamkit::python
