#pragma once
// What `track` and `run` share: the summary lines of a run and its evaluation against the
// sequence's groundtruth (the same as `slamkit eval all GT RUN/trajectory.txt --out RUN`).
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "core/progress.h"
#include "io/tum_sequence.h"
#include "pipeline/batch_engine.h"

namespace slamkit::cli {

// Frames, keyframes, lost frames and why, solvers, speed.
void print_tracking_summary(const TumSequence& sequence, const RunResult& result);

// ATE and RPE of RUN/trajectory.txt, written into the run folder, and their plots unless
// `plot` is false; says so when the sequence has no groundtruth.
void evaluate_run_folder(const TumSequence& sequence, const std::filesystem::path& out, bool plot);

// The loops of RUN/loops.csv judged against the groundtruth (and revisits.txt when the
// sequence has one): printed, and added to RUN/metrics.json.
void evaluate_run_loops(const TumSequence& sequence, const std::filesystem::path& out);

// One progress bar per stage, drawn on stderr as the stages report.
class StageProgress {
 public:
  void operator()(const std::string& stage, size_t done, size_t total);

 private:
  std::map<std::string, std::unique_ptr<Progress>> bars_;
};

}  // namespace slamkit::cli
