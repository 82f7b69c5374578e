#pragma once
// A run's folder (docs/method.md#architecture): trajectory.txt and keyframes.txt (TUM format),
// tracking.csv (one row a frame), mapping.csv (one row a keyframe), settings.yaml and
// camera.yaml (to reproduce it), timing.json; with the back end, trajectory_tracked.txt (the
// poses before its corrections reached the frames).
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "core/camera.h"
#include "core/settings/settings.h"
#include "pipeline/batch_engine.h"

namespace slamkit {

void write_run_outputs(const std::filesystem::path& dir, const std::string& sequence_name,
                       const Camera& camera, const Settings& settings, const RunResult& result);
// timing.json, written after the other outputs so that it holds the time they took.
void write_timing_json(const std::filesystem::path& dir, const std::string& sequence_name,
                       const RunResult& result);

// run.json, what readers check before trusting a run folder. begin_run_folder creates the
// folder and writes it with status "running"; with kEndProcess, until write_run_status, SIGINT
// or SIGTERM removes any half-written output, rewrites it as "interrupted" and ends the process
// with 128 + signal (the CLI). kRaise leaves signals to the caller, which stops the work by
// throwing RunInterrupted (the Python module, where Ctrl-C must not end the interpreter).
// write_run_status, called after every other file, writes "complete": version, settings hash
// (FNV-1a 64 of settings.yaml's text), start and end (UTC), stage seconds.
struct RunStart {
  std::filesystem::path dir;
  std::string settings_hash;
  std::string started;
  bool handles_signals = false;  // this folder's handler is installed (kEndProcess)
};
enum class OnSignal { kEndProcess, kRaise };
RunStart begin_run_folder(const std::filesystem::path& dir, const Settings& settings,
                          OnSignal on_signal = OnSignal::kEndProcess);
void write_run_status(const RunStart& run, const StageTimes& seconds);

// Thrown through a run to stop it on a signal the caller caught.
struct RunInterrupted : std::runtime_error {
  explicit RunInterrupted(int signal_number)
      : std::runtime_error("interrupted by signal " + std::to_string(signal_number)),
        signal(signal_number) {}
  int signal;
};

// Calls work(), which writes the folder's other files and returns the stage times, then
// write_run_status. When work throws (a frame that cannot be read), run.json says "failed" with
// the message, which readers refuse as they refuse an interrupted run, and the exception goes on;
// RunInterrupted makes it "interrupted" with the signal, as the CLI's handler writes it.
void fill_run_folder(const RunStart& run, const std::function<StageTimes()>& work);

// {"prepare": s, "track": s, ...}: the stage times as run.json holds them.
nlohmann::json stage_seconds_json(const StageTimes& seconds);

// Per-stage statistics of a run, as written to timing.json.
struct StageStats {
  std::string name;
  double median_ms = 0, mean_ms = 0, max_ms = 0;
};
struct TimingSummary {
  std::vector<StageStats> stages;
  double tracking_median_ms = 0;  // everything after image decode, per frame
  double frames_per_second = 0;   // frames over the whole run's wall time
};
TimingSummary summarise_timing(const RunResult& result);

// Where tracking failed and how soon it came back, one line per failure episode
// ("frames 120-121 lost (implausible jump); tracking recovered at frame 122").
std::vector<std::string> describe_failures(const RunResult& result);

}  // namespace slamkit
