#include "bin/run_summary.h"

#include <cstdio>

#include "eval/metrics/ate.h"
#include "pipeline/run_output.h"

namespace slamkit::cli {

void print_tracking_summary(const TumSequence& seq, const RunResult& result) {
  int lost = 0, keyframes = 0, svd = 0, dense = 0;
  for (const TrackedFrame& f : result.frames) {
    lost += f.lost;
    keyframes += f.keyframe;
    svd += f.solver == PoseSolver::kSvdRansac && !f.lost;
    dense += f.solver == PoseSolver::kPointToPlane && !f.lost;
  }
  const TimingSummary timing = summarise_timing(result);
  std::printf("tracked     %zu frames of %s: %d keyframes, %d lost\n", result.frames.size(),
              seq.folder().filename().string().c_str(), keyframes, lost);
  std::printf("solvers     svd_ransac %d, point_to_plane %d, motion_model %d\n", svd, dense, lost);
  for (const std::string& line : describe_failures(result))
    std::printf("failure     %s\n", line.c_str());
  std::printf("speed       %.1f frames/s with %d threads; tracking median %.1f ms/frame\n",
              timing.frames_per_second, result.threads, timing.tracking_median_ms);
}

void print_back_end_summary(const TumSequence& seq, const Settings& settings,
                            const RunResult& result) {
  int local_runs = 0, removed = 0;
  for (const MappingReport& r : result.keyframe_reports) {
    local_runs += r.ba_run;
    removed += r.ba.removed_observations;
  }
  const StageTimes& t = result.seconds;
  std::printf("map         %d keyframes (%d redundant ones culled), %d points\n",
              result.map.num_active_keyframes(), result.map.num_culled_keyframes(),
              result.map.num_good_points());
  std::printf("local BA    %d of %zu keyframes, %d outlier observations removed, %.2f s\n",
              local_runs, result.keyframe_reports.size(), removed, t.local_ba);
  const LoopPassReport& lp = result.loop_pass;
  if (lp.ran) {
    int verified = 0;
    for (const LoopDecision& d : lp.decisions) verified += d.verified;
    std::printf(
        "loops       %zu accepted of %d candidates verified (%zu judged, loops.csv); "
        "%d points fused; %.2f s (vocabulary of %zu words %.2f, detection %.2f, "
        "correction %.2f)\n",
        lp.loops.size(), verified, lp.decisions.size(), lp.fused_points, t.loops,
        lp.vocabulary_words, lp.vocabulary_seconds, lp.detection_seconds, lp.correction_seconds);
  }
  if (result.global_ba_run)
    std::printf("global BA   %d keyframes, %d points, %d iterations, %d outliers removed, %.2f s\n",
                result.global_ba.free_keyframes + result.global_ba.fixed_keyframes,
                result.global_ba.points, result.global_ba.report.iterations,
                result.global_ba.removed_observations, t.global_ba);
  if (settings.optimization.refine_frames)
    std::printf("refinement  %d of %zu frames solved again against the final map, %.2f s\n",
                result.refined_frames, result.frames.size(), t.refine);
  const FusionReport& fused = result.fusion;
  if (fused.frames > 0 && fused.method == MapMethod::kTsdf)
    std::printf(
        "fused map   %zu frames: %zu depth samples into a %.0f mm TSDF (%zu blocks, %.0f MB), "
        "%zu surface points%s, %.2f s\n",
        fused.frames, fused.raw_points, settings.map.voxel_size * 1000, fused.blocks,
        fused.volume_mb, fused.points,
        fused.triangles > 0 ? (", " + std::to_string(fused.triangles) + " triangles").c_str() : "",
        t.fusion);
  else if (fused.frames > 0)
    std::printf(
        "fused map   %zu frames: %zu points raw, %zu after the %.0f mm voxel grid, %zu after "
        "outlier removal, %.2f s\n",
        fused.frames, fused.raw_points, fused.after_voxel_grid, settings.map.voxel_size * 1000,
        fused.points, t.fusion);
  if (result.fusion.beyond_grid > 0)
    std::fprintf(stderr,
                 "warning: %zu map points lie over 2^20 voxels (10 km at 1 cm) from the origin and "
                 "were left "
                 "out of map.ply (a trajectory that flew off?)\n",
                 result.fusion.beyond_grid);
  if (seq.groundtruth() && settings.pipeline.evaluate)
    std::printf("ATE RMSE    %.2f mm as tracked, %.2f mm after the back end\n",
                1000 * eval::ate_rmse(*seq.groundtruth(), result.tracked_trajectory()),
                1000 * eval::ate_rmse(*seq.groundtruth(), result.trajectory()));
  std::printf(
      "stages      prepare %.2f s (parallel, beside tracking), track %.2f s (local BA "
      "%.2f), loops %.2f, global BA %.2f, refinement %.2f, fusion %.2f, write %.2f; total "
      "%.2f s, %.1f frames/s\n",
      t.prepare, t.track, t.local_ba, t.loops, t.global_ba, t.refine, t.fusion, t.write, t.total,
      double(result.frames.size()) / t.total);
  const StageTimes& cpu = result.cpu_seconds;
  std::printf(
      "CPU         track %.2f s (with preparation and local BA), loops %.2f, global BA "
      "%.2f, refinement %.2f, fusion %.2f, write %.2f; total %.2f s; peak memory %.0f MB\n",
      cpu.track, cpu.loops, cpu.global_ba, cpu.refine, cpu.fusion, cpu.write, cpu.total,
      result.peak_rss_mb);
}

void StageProgress::operator()(const std::string& stage, size_t done, size_t total) {
  std::unique_ptr<Progress>& bar = bars_[stage];
  if (!bar) bar = std::make_unique<Progress>(stage, total);
  bar->update(done);
}

}  // namespace slamkit::cli
