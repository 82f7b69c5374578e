#pragma once
// A run folder judged against its sequence's groundtruth, as `slamkit run` and `track` do at
// the end: the trajectory (as `slamkit eval all GT RUN/trajectory.txt --out RUN`), the loops
// and, on a synthetic sequence, the fused map. Each writes into RUN/metrics.json and prints
// its summary lines unless `quiet`.
#include <filesystem>

#include "eval/plotting.h"
#include "io/tum_sequence.h"

namespace slamkit::eval {

// ATE and RPE of RUN/trajectory.txt, written into the run folder, and their plots (as
// `figures` says) unless `plot` is false; says so when the sequence has no groundtruth.
void evaluate_run_folder(const TumSequence& sequence, const std::filesystem::path& out, bool plot,
                         bool quiet = false, const FigureFiles& figures = {});

// The loops of RUN/loops.csv judged against the groundtruth (and revisits.txt when the
// sequence has one): printed, added to RUN/metrics.json, and each loop's verdict written to
// RUN/loop_check.csv.
void evaluate_run_loops(const TumSequence& sequence, const std::filesystem::path& out,
                        bool quiet = false);

// On a synthetic sequence, RUN/map.ply's accuracy and completeness (surfaces within
// `max_depth` metres of the cameras, as the map was fused): printed, and added to
// RUN/metrics.json. Nothing on a recorded sequence.
void evaluate_run_map(const TumSequence& sequence, double max_depth,
                      const std::filesystem::path& out, bool quiet = false);

}  // namespace slamkit::eval
