#pragma once
// The batch engine (DESIGN): reads a whole sequence, prepares frames in parallel chunks, and
// tracks them in order. Later stages (bundle adjustment, loop closing, fusion) plug in after.
#include <functional>
#include <vector>

#include "core/settings/settings.h"
#include "core/trajectory.h"
#include "io/tum_sequence.h"
#include "map/map.h"
#include "tracking/tracked_frame.h"

namespace slamkit {

struct FrameTiming {
  double decode_ms = 0, features_ms = 0, window_code_ms = 0;  // parallel stage, per frame
};

struct RunResult {
  std::vector<TrackedFrame> frames;  // one per associated frame, in order
  std::vector<FrameTiming> timing;   // one per frame
  Map map;
  double prepare_seconds = 0;  // wall time of the parallel stage
  double track_seconds = 0;    // wall time of sequential tracking
  int threads = 1;

  Trajectory trajectory() const;
  Trajectory keyframe_trajectory() const;
};

// Called after each tracked frame with (frames done, total).
using ProgressCallback = std::function<void(size_t, size_t)>;

// Throws InputError for unreadable frames (naming the file).
RunResult run_batch(const TumSequence& sequence, const Settings& settings,
                    const ProgressCallback& progress = {});

}  // namespace slamkit
