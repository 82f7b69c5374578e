#include "pipeline/run_pipeline.h"

#include <malloc.h>

#include <optional>

#include "core/stopwatch.h"
#include "pipeline/run_output.h"

namespace slamkit {

namespace {

// The wall time of one stage, seconds.
template <class Stage>
double seconds_of(Stage&& stage) {
  Stopwatch watch;
  stage();
  return watch.lap() / 1000.0;
}

}  // namespace

RunResult run_batch(const TumSequence& sequence, const Settings& settings,
                    const std::filesystem::path& out, const std::string& sequence_name,
                    const ProgressCallback& progress, const Vocabulary* vocabulary) {
  Stopwatch total;
  const Camera& camera = sequence.camera();
  std::filesystem::create_directories(out);
  RunResult result = track_sequence(sequence, settings, progress);
  // Hands the memory tracking freed back to the system: glibc keeps it in the threads' arenas,
  // and the fusion peak came on top of it (desk 600: 834 -> 527 MB, outputs identical;
  // docs/experiments.md).
  malloc_trim(0);
  StageTimes& t = result.seconds;
  t.loops =
      seconds_of([&] { result.loop_pass = close_loops(result.map, camera, settings, vocabulary); });
  t.global_ba = seconds_of([&] {
    if (const std::optional<MapAdjustment> adjustment =
            adjust_globally(result.map, camera, settings)) {
      result.global_ba = *adjustment;
      result.global_ba_run = adjustment->report.solved;
    }
  });
  reanchor_frames(result.map, result.frames);
  malloc_trim(0);  // and what the back end freed, before fusion's peak
  t.fusion = seconds_of([&] {
    result.fusion = fuse_final_map(result.map, result.frames, std::move(result.keyframe_samples),
                                   sequence, settings, out / "map.ply", progress);
  });
  t.write = seconds_of([&] { write_run_outputs(out, sequence_name, camera, settings, result); });
  t.total = total.lap() / 1000.0;
  write_timing_json(out, sequence_name, result);
  return result;
}

Settings front_end_only(Settings settings) {
  settings.optimization.local_ba.enabled = false;
  settings.optimization.global_ba.enabled = false;
  settings.loop.enabled = false;
  settings.map.enabled = false;
  return settings;
}

}  // namespace slamkit
