#include "pipeline/run_pipeline.h"

#include "core/stopwatch.h"
#include "pipeline/run_output.h"

namespace slamkit {

RunResult run_batch(const TumSequence& sequence, const Settings& settings,
                    const std::filesystem::path& out, const std::string& sequence_name,
                    const ProgressCallback& progress, const Vocabulary* vocabulary) {
  Stopwatch total, write;
  std::filesystem::create_directories(out);
  RunResult result = track_sequence(sequence, settings, progress);
  close_loops_of(result, sequence.camera(), settings, vocabulary);
  adjust_globally(result, sequence.camera(), settings);
  reanchor_frames(result);
  fuse_final_map(result, sequence, settings, out / "map.ply", progress);
  write.lap();
  write_run_outputs(out, sequence_name, sequence.camera(), settings, result);
  result.seconds.write = write.lap() / 1000.0;
  result.seconds.total = total.lap() / 1000.0;
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
