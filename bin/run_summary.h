#pragma once
// What `track` and `run` share: the summary lines of a run and its progress bars (the run's
// evaluation is eval/run/run_evaluation.h).
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "core/progress.h"
#include "core/settings/settings.h"
#include "io/tum_sequence.h"
#include "pipeline/batch_engine.h"

namespace slamkit::cli {

// Frames, keyframes, lost frames and why, solvers, speed.
void print_tracking_summary(const TumSequence& sequence, const RunResult& result);

// The back end's stages (map, local and global BA, loops, refinement, fusion), ATE as tracked
// and after the back end, stage times, CPU and peak memory.
void print_back_end_summary(const TumSequence& sequence, const Settings& settings,
                            const RunResult& result);

// One progress bar per stage, drawn on stderr as the stages report.
class StageProgress {
 public:
  void operator()(const std::string& stage, size_t done, size_t total);

 private:
  std::map<std::string, std::unique_ptr<Progress>> bars_;
};

}  // namespace slamkit::cli
