#include "pipeline/run_pipeline.h"

#include <malloc.h>
#include <sys/resource.h>

#include <optional>

#include "core/stopwatch.h"
#include "pipeline/run_output.h"
#include "tracking/frame_refinement.h"

namespace slamkit {

namespace {

// Runs one stage, adding its wall and process CPU seconds to `wall` and `cpu`.
template <class Stage>
void time_stage(double& wall, double& cpu, Stage&& stage) {
  Stopwatch watch;
  CpuStopwatch cpu_watch;
  stage();
  wall += watch.lap() / 1000.0;
  cpu += cpu_watch.lap() / 1000.0;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

}  // namespace

RunResult run_batch(const TumSequence& sequence, const Settings& settings,
                    const std::filesystem::path& out, const std::string& sequence_name,
                    const ProgressCallback& progress, const Vocabulary* vocabulary) {
  Stopwatch total;
  CpuStopwatch total_cpu;
  const Camera& camera = sequence.camera();
  std::filesystem::create_directories(out);
  RunResult result = track_sequence(sequence, settings, progress);
  result.cpu_seconds.track = total_cpu.lap() / 1000.0;
  // Hands the memory tracking freed back to the system: glibc keeps it in the threads' arenas,
  // and the fusion peak came on top of it (desk 600: 834 -> 527 MB, outputs identical;
  // docs/measurement-log/experiments.md).
  malloc_trim(0);
  StageTimes& t = result.seconds;
  StageTimes& cpu = result.cpu_seconds;
  time_stage(t.loops, cpu.loops,
             [&] { result.loop_pass = close_loops(result.map, camera, settings, vocabulary); });
  time_stage(t.global_ba, cpu.global_ba, [&] {
    if (const std::optional<MapAdjustment> adjustment =
            adjust_globally(result.map, camera, settings)) {
      result.global_ba = *adjustment;
      result.global_ba_run = adjustment->report.solved;
    }
  });
  reanchor_frames(result.map, result.frames);
  time_stage(t.refine, cpu.refine, [&] {
    if (settings.optimization.refine_frames)
      result.refined_frames =
          refine_frames(result.map, camera, settings.tracking.motion_ba, result.frames);
  });
  malloc_trim(0);  // and what the back end freed, before fusion's peak
  time_stage(t.fusion, cpu.fusion, [&] {
    result.fusion = fuse_final_map(result.map, result.frames, std::move(result.keyframe_samples),
                                   sequence, settings, out / "map.ply", progress);
  });
  result.peak_rss_mb = peak_rss_mb();
  time_stage(t.write, cpu.write,
             [&] { write_run_outputs(out, sequence_name, camera, settings, result); });
  t.total = total.lap() / 1000.0;
  cpu.total = cpu.track + cpu.loops + cpu.global_ba + cpu.refine + cpu.fusion + cpu.write;
  write_timing_json(out, sequence_name, result);
  return result;
}

Settings front_end_only(Settings settings) {
  settings.optimization.local_ba.enabled = false;
  settings.optimization.global_ba.enabled = false;
  settings.optimization.refine_frames = false;
  settings.loop.enabled = false;
  settings.map.enabled = false;
  return settings;
}

}  // namespace slamkit
