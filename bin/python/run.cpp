// slamkit.run and slamkit.track: `slamkit run` and `slamkit track` from Python, through the
// function the CLI calls (bin/run_job.h), so a run folder written from Python is the CLI's. The
// GIL is released while the pipeline works; Ctrl-C (or an exception from the progress callback)
// stops the run at the next frame or fused batch, marks the folder "interrupted" (or "failed")
// and is raised in Python.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <stdlib.h>

#include <csignal>
#include <fstream>
#include <optional>
#include <sstream>

#include "bin/output_folder.h"
#include "bin/python/bindings.h"
#include "bin/python/option_values.h"
#include "bin/python/settings_from_python.h"
#include "bin/run_job.h"
#include "fusion/ply_cloud.h"
#include "io/trajectory_io.h"
#include "loop/vocabulary_file.h"
#include "pipeline/run_pipeline.h"

namespace slamkit::python {
namespace {

namespace py = pybind11;
namespace fs = std::filesystem;
using namespace pybind11::literals;

// Called by the pipeline on the thread that started the run (outside any parallel region), with
// the GIL released: Python's pending signals are handled here, so Ctrl-C reaches the run.
struct RunProgressRelay {
  py::object callback;
  std::optional<py::error_already_set> error;

  void operator()(const std::string& stage, size_t done, size_t total) {
    py::gil_scoped_acquire acquire;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!callback.is_none()) callback(stage, done, total);
    } catch (py::error_already_set& e) {
      const bool interrupt = e.matches(PyExc_KeyboardInterrupt);
      const std::string what = e.what();
      error = std::move(e);
      if (interrupt) throw RunInterrupted(SIGINT);
      throw std::runtime_error("the progress callback raised " + what);
    }
  }
};

// A folder for a run whose files the caller does not keep (out=None), removed on every way out.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string name = (fs::temp_directory_path() / "slamkit_run.XXXXXX").string();
    if (!mkdtemp(name.data())) throw std::runtime_error("cannot create a folder in " + name);
    path_ = name;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

py::object trajectory_object(Trajectory trajectory) {
  auto file = std::make_shared<TrajectoryFile>();
  file->trajectory = std::move(trajectory);
  return py::cast(file);
}

py::object json_file(const fs::path& path) {
  if (!fs::exists(path)) return py::none();
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return py::module_::import("json").attr("loads")(text.str());
}

// map.ply as arrays: points (N, 3) float64, colours (N, 3) uint8 RGB, normals (N, 3) or None.
struct MapArrays {
  py::object points = py::none(), colours = py::none(), normals = py::none();
};
MapArrays map_arrays(const fs::path& ply) {
  if (!fs::exists(ply)) return {};
  const PlyCloud cloud = read_ply_cloud(ply);
  const auto n = py::ssize_t(cloud.points.size());
  py::array_t<double> points({n, py::ssize_t(3)});
  py::array_t<uint8_t> colours({n, py::ssize_t(3)});
  auto p = points.mutable_unchecked<2>();
  auto c = colours.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t k = 0; k < 3; ++k) {
      p(i, k) = cloud.points[size_t(i)][k];
      c(i, k) = cloud.colours[size_t(i)][size_t(k)];
    }
  if (cloud.normals.empty()) return {points, colours, py::none()};
  py::array_t<double> normals({n, py::ssize_t(3)});
  auto m = normals.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t k = 0; k < 3; ++k) m(i, k) = cloud.normals[size_t(i)][k];
  return {points, colours, normals};
}

py::object run_output(const RunResult& result, const fs::path& folder, bool keep_folder,
                      bool back_end) {
  std::vector<bool> lost;
  for (const TrackedFrame& f : result.frames) lost.push_back(f.lost);
  py::array_t<bool> lost_array(py::ssize_t(lost.size()));
  for (size_t i = 0; i < lost.size(); ++i) lost_array.mutable_at(py::ssize_t(i)) = lost[i];
  const TimingSummary timing = summarise_timing(result);
  const MapArrays map = map_arrays(folder / "map.ply");
  const auto json = py::module_::import("json");
  return py::module_::import("types").attr("SimpleNamespace")(
      "trajectory"_a = trajectory_object(result.trajectory()),
      "tracked_trajectory"_a =
          trajectory_object(back_end ? result.tracked_trajectory() : result.trajectory()),
      "keyframes"_a = trajectory_object(result.keyframe_trajectory()), "lost"_a = lost_array,
      "frames_lost"_a = std::count(lost.begin(), lost.end(), true),
      "failures"_a = describe_failures(result),
      "seconds"_a = json.attr("loads")(stage_seconds_json(result.seconds).dump()),
      "cpu_seconds"_a = json.attr("loads")(stage_seconds_json(result.cpu_seconds).dump()),
      "peak_memory_mb"_a = result.peak_rss_mb, "frames_per_second"_a = timing.frames_per_second,
      "map_points"_a = map.points, "map_colours"_a = map.colours, "map_normals"_a = map.normals,
      "metrics"_a = keep_folder ? json_file(folder / "metrics.json") : py::none(),
      "out"_a = keep_folder ? py::cast(folder) : py::none());
}

// The sequence argument: a slamkit.Sequence, or a folder opened with the defaults.
const TumSequence& sequence_of(const py::object& given, std::optional<TumSequence>& opened) {
  if (py::isinstance<TumSequence>(given)) return given.cast<const TumSequence&>();
  const fs::path folder = given.cast<fs::path>();
  py::gil_scoped_release release;
  opened = TumSequence::open(folder);
  return *opened;
}

py::object run_from_python(const py::object& sequence_arg, const py::object& settings_arg,
                           const std::optional<fs::path>& out, std::optional<int> threads,
                           const std::optional<fs::path>& vocabulary_file, bool plot,
                           const py::object& plot_format, const py::object& dpi_arg,
                           const py::object& progress, bool verbose, bool back_end) {
  if (out) cli::check_output_folder("out", *out);
  std::optional<TumSequence> opened;
  const TumSequence& seq = sequence_of(sequence_arg, opened);
  if (out) cli::check_output_outside_sequences("out", *out, {seq.folder().string()}, false);
  cli::RunJob job;
  job.settings = settings_from_python(settings_arg);
  if (threads) {
    if (*threads < 0)
      throw py::value_error("threads " + std::to_string(*threads) + ": not >= 0 (0: all cores)");
    job.settings.pipeline.threads = *threads;
  }
  if (!back_end) job.settings = front_end_only(job.settings);
  if (!out) {  // nothing is kept, so nothing is evaluated or drawn
    job.settings.pipeline.evaluate = false;
    job.settings.report.enabled = false;
  }
  job.back_end = back_end;
  job.plot = plot;
  if (!plot_format.is_none()) job.figures.formats = plot_formats(plot_format);
  if (!dpi_arg.is_none()) job.figures.dpi = dpi(dpi_arg);
  job.quiet = !verbose;
  job.progress_bars = verbose;
  job.on_signal = OnSignal::kRaise;
  std::optional<Vocabulary> vocabulary;
  if (vocabulary_file) {
    py::gil_scoped_release release;
    vocabulary = load_vocabulary(*vocabulary_file);
  }
  job.vocabulary = vocabulary ? &*vocabulary : nullptr;

  std::optional<ScratchFolder> scratch;
  if (!out) scratch.emplace();
  const fs::path folder = out ? *out : scratch->path();
  RunProgressRelay relay{progress, std::nullopt};
  RunResult result;
  try {
    py::gil_scoped_release release;
    result = cli::run_into_folder(seq, folder, job, std::ref(relay));
  } catch (const std::exception&) {
    if (relay.error) throw std::move(*relay.error);  // the Python exception that stopped it
    throw;
  }
  return run_output(result, folder, out.has_value(), back_end);
}

constexpr const char* kResultDoc =
    "Returns an object with .trajectory, .tracked_trajectory (before the back end's "
    "corrections), .keyframes (slamkit.Trajectory each), .lost (bool per frame), .frames_lost, "
    ".failures (one line per lost episode), .seconds and .cpu_seconds (per stage, as run.json), "
    ".peak_memory_mb, .frames_per_second, .map_points (N, 3), .map_colours (N, 3) uint8 RGB, "
    ".map_normals (N, 3) (None without a map), .metrics (metrics.json as a dict, or None) and "
    ".out. ";

}  // namespace

void bind_run(py::module_& m) {
  const std::string run_doc =
      std::string(
          "`slamkit run`: the whole pipeline over a TUM sequence (a slamkit.Sequence or a "
          "folder). settings: a nested dict or a YAML path, as settings() takes (threads= "
          "overrides pipeline.threads). With out=, the run folder `slamkit run --out` writes, "
          "byte for byte but for run.json's times, with its evaluation, plots (plot=False: "
          "none; plot_format= and dpi= as --plot-format and --dpi) and report.html as the "
          "settings say; without, a temporary folder, removed. "
          "vocabulary: the loop pass's (slamkit vocab train, or ORBvoc.txt). progress(stage, "
          "done, total) is called as frames are tracked and fused. Ctrl-C, or an exception "
          "from progress, stops the run at the next frame or fused batch and is raised; the "
          "folder says \"interrupted\" (\"failed\"). verbose: print the CLI's lines and bars. ") +
      kResultDoc;
  m.def(
      "run",
      [](const py::object& sequence, const py::object& settings,
         const std::optional<fs::path>& out, std::optional<int> threads,
         const std::optional<fs::path>& vocabulary, bool plot, const py::object& plot_format,
         const py::object& dots, const py::object& progress, bool verbose) {
        return run_from_python(sequence, settings, out, threads, vocabulary, plot, plot_format,
                               dots, progress, verbose, true);
      },
      "sequence"_a, "settings"_a = py::none(), "out"_a = py::none(), py::kw_only(),
      "threads"_a = py::none(), "vocabulary"_a = py::none(), "plot"_a = true,
      "plot_format"_a = py::none(), "dpi"_a = py::none(), "progress"_a = py::none(),
      "verbose"_a = false, run_doc.c_str());
  const std::string track_doc =
      std::string(
          "`slamkit track`: the front end alone (no bundle adjustment, loop pass or map), "
          "otherwise as run(). ") +
      kResultDoc;
  m.def(
      "track",
      [](const py::object& sequence, const py::object& settings,
         const std::optional<fs::path>& out, std::optional<int> threads, bool plot,
         const py::object& plot_format, const py::object& dots, const py::object& progress,
         bool verbose) {
        return run_from_python(sequence, settings, out, threads, std::nullopt, plot, plot_format,
                               dots, progress, verbose, false);
      },
      "sequence"_a, "settings"_a = py::none(), "out"_a = py::none(), py::kw_only(),
      "threads"_a = py::none(), "plot"_a = true, "plot_format"_a = py::none(),
      "dpi"_a = py::none(), "progress"_a = py::none(), "verbose"_a = false, track_doc.c_str());
}

}  // namespace slamkit::python
