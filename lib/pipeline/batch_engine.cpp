#include "pipeline/batch_engine.h"

#include <omp.h>

#include <algorithm>

#include "core/stopwatch.h"
#include "keyframes/window_code.h"
#include "pipeline/frame_preparation.h"
#include "tracking/tracker.h"

namespace slamkit {

Trajectory RunResult::trajectory() const {
  Trajectory t;
  for (const TrackedFrame& f : frames) t.push_back(f.stamp, f.T_w_c);
  return t;
}

Trajectory RunResult::keyframe_trajectory() const {
  Trajectory t;
  for (const Keyframe& k : map.keyframes()) t.push_back(k.stamp, k.T_w_c);
  return t;
}

RunResult run_batch(const TumSequence& sequence, const Settings& settings,
                    const ProgressCallback& progress) {
  RunResult result;
  result.threads = settings.pipeline.threads > 0 ? settings.pipeline.threads : omp_get_num_procs();
  omp_set_num_threads(result.threads);
  const Camera& camera = sequence.camera();
  const WindowPattern pattern({camera.width, camera.height}, settings.keyframes);
  Tracker tracker(camera, settings);
  const size_t chunk = size_t(std::max(1, settings.pipeline.chunk_frames));
  for (size_t begin = 0; begin < sequence.size(); begin += chunk) {
    const size_t end = std::min(sequence.size(), begin + chunk);
    Stopwatch watch;
    const std::vector<PreparedFrame> frames =
        prepare_frames(sequence, begin, end, settings, pattern);
    result.prepare_seconds += watch.lap() / 1000.0;
    for (const PreparedFrame& frame : frames) {
      result.frames.push_back(tracker.track(frame));
      result.timing.push_back({frame.decode_ms, frame.features_ms, frame.window_code_ms});
      if (progress) progress(result.frames.size(), sequence.size());
    }
    result.track_seconds += watch.lap() / 1000.0;
  }
  result.map = tracker.map();
  return result;
}

}  // namespace slamkit
