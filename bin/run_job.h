#pragma once
// What `slamkit run` and `slamkit track` do once their options are read: the run into its
// folder, its evaluation and its page. The Python module calls the same function, so that a run
// started there writes the folder the CLI writes.
#include <filesystem>

#include "eval/plotting.h"
#include "io/tum_sequence.h"
#include "loop/vocabulary.h"
#include "pipeline/batch_engine.h"
#include "pipeline/run_output.h"

namespace slamkit::cli {

struct RunJob {
  Settings settings;       // with the command's options applied
  bool back_end = true;    // false: `track`, the front end alone (settings made front_end_only)
  bool plot = true;        // the evaluation's plots
  eval::FigureFiles figures;  // their files (--plot-format, --pdf, --dpi)
  bool quiet = false;      // no summary lines on stdout
  bool progress_bars = true;
  OnSignal on_signal = OnSignal::kEndProcess;
  const Vocabulary* vocabulary = nullptr;  // the loop pass's; nullptr: trained on the keyframes
};

// Writes the run folder `out` (run.json last), evaluates it when settings.pipeline.evaluate
// (against the sequence's groundtruth, if any) and, for `run`, writes report.html when
// settings.report.enabled. `progress` is called as the stages advance, beside the bars.
RunResult run_into_folder(const TumSequence& sequence, const std::filesystem::path& out,
                          const RunJob& job, const ProgressCallback& progress = {});

}  // namespace slamkit::cli
