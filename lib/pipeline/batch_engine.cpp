#include "pipeline/batch_engine.h"

#include <omp.h>

#include <algorithm>
#include <future>

#include "core/pose.h"
#include "core/stopwatch.h"
#include "keyframes/window_code.h"
#include "pipeline/frame_preparation.h"
#include "tracking/tracker.h"

namespace slamkit {

Trajectory RunResult::trajectory() const {
  Trajectory t;
  for (const TrackedFrame& f : frames)
    if (!f.lost || lost_frames == LostFrames::kMotionModel) t.push_back(f.stamp, f.T_w_c);
  return t;
}

Trajectory RunResult::tracked_trajectory() const {
  Trajectory t;
  for (size_t i = 0; i < frames.size(); ++i)
    if (!frames[i].lost || lost_frames == LostFrames::kMotionModel)
      t.push_back(frames[i].stamp, tracked_poses[i]);
  return t;
}

Trajectory RunResult::keyframe_trajectory() const {
  Trajectory t;
  for (const Keyframe& k : map.keyframes())
    if (!k.culled) t.push_back(k.stamp, k.T_w_c);
  return t;
}

namespace {

int thread_count(const Settings& settings) {
  return settings.pipeline.threads > 0 ? settings.pipeline.threads : omp_get_num_procs();
}

Map empty_map(const Settings& settings) {
  return Map({settings.orb.pyramid_levels, settings.orb.scale_factor},
             settings.mapping.covisibility_min_shared);
}

}  // namespace

RunResult track_sequence(const TumSequence& sequence, const Settings& settings,
                         const ProgressCallback& progress) {
  Stopwatch total;
  RunResult result;
  result.map = empty_map(settings);
  result.threads = thread_count(settings);
  result.lost_frames = settings.pipeline.lost_frames;
  omp_set_num_threads(result.threads);
  const Camera& camera = sequence.camera();
  const WindowPattern pattern({camera.width, camera.height}, settings.keyframes);
  Tracker tracker(camera, settings, result.map);
  LocalMapper mapper(camera, settings, result.map, result.threads > 1);
  const size_t chunk = size_t(std::max(1, settings.pipeline.chunk_frames));

  // The next chunk is prepared while this one is tracked, so both cores stay busy. Frames
  // are prepared independently, so the overlap changes no result. One thread: no overlap.
  auto prepare = [&](size_t begin) {
    omp_set_num_threads(result.threads);  // a new thread starts with OpenMP's defaults
    Stopwatch watch;
    std::vector<PreparedFrame> frames = prepare_frames(
        sequence, begin, std::min(sequence.size(), begin + chunk), settings, pattern);
    return std::make_pair(std::move(frames), watch.lap() / 1000.0);
  };
  const auto policy = result.threads > 1 ? std::launch::async : std::launch::deferred;
  std::future<std::pair<std::vector<PreparedFrame>, double>> next;
  if (sequence.size() > 0) next = std::async(policy, prepare, size_t(0));
  size_t last_keyframe_frame = 0;
  result.keyframe_samples = KeyframeSamples(settings.map);
  auto release_culled_samples = [&] {
    if (!settings.mapping.cull_keyframes) return;  // no scan per keyframe when nothing is culled
    result.keyframe_samples.release([&](size_t k) { return result.map.keyframe(int(k)).culled; });
  };
  for (size_t begin = 0; begin < sequence.size(); begin += chunk) {
    auto [frames, prepare_seconds] = next.get();
    result.seconds.prepare += prepare_seconds;
    if (begin + chunk < sequence.size()) next = std::async(policy, prepare, begin + chunk);
    // While the next chunk is prepared on every core, the tracker's parallel loops take one
    // thread: two teams on two cores wait on each other's spinning threads (lowtexture 600,
    // whose dense frames have such loops: 6.2 s -> 5.9 s). Their results do not depend on it.
    omp_set_num_threads(next.valid() ? 1 : result.threads);
    Stopwatch watch;
    for (PreparedFrame& frame : frames) {
      TrackedFrame record = tracker.track(frame);
      FrameTiming timing{frame.decode_ms, frame.features_ms, frame.window_code_ms};
      if (record.keyframe) {
        std::vector<Eigen::Isometry3d> since_keyframe(
            result.tracked_poses.begin() + long(last_keyframe_frame), result.tracked_poses.end());
        since_keyframe.push_back(record.T_w_c);
        const double motion = quasi_static_motion(
            since_keyframe, settings.optimization.local_ba.motion_rotation_weight);
        record.reference_keyframe =
            mapper.insert_keyframe(tracker.keyframe_from(frame, record), motion);
        release_culled_samples();
        result.keyframe_samples.add(frame.rgb, frame.depth);
        record.T_ref_c = Eigen::Isometry3d::Identity();
        timing.mapping_ms = mapper.reports().back().ms;
        last_keyframe_frame = result.frames.size();
      }
      result.tracked_poses.push_back(record.T_w_c);
      result.frames.push_back(std::move(record));
      result.timing.push_back(timing);
      if (progress) progress("track", result.frames.size(), sequence.size());
    }
    result.seconds.track += watch.lap() / 1000.0;
  }
  omp_set_num_threads(result.threads);
  Stopwatch last_ba;
  mapper.finish();
  release_culled_samples();
  result.seconds.track += last_ba.lap() / 1000.0;
  result.keyframe_reports = mapper.reports();
  for (const MappingReport& r : result.keyframe_reports)
    result.seconds.local_ba += r.ba.report.seconds;
  // Local BA's corrections reach the frames tracked before them.
  if (settings.optimization.local_ba.enabled) reanchor_frames(result.map, result.frames);
  result.seconds.total = total.lap() / 1000.0;
  return result;
}

std::optional<MapAdjustment> adjust_globally(Map& map, const Camera& camera,
                                             const Settings& settings) {
  if (!settings.optimization.global_ba.enabled || map.keyframes().size() < 2) return std::nullopt;
  return adjust_whole_map(map, camera, settings.optimization);
}

void reanchor_frames(Map& map, std::vector<TrackedFrame>& frames) {
  map.place_culled_keyframes();
  for (TrackedFrame& f : frames)
    if (f.reference_keyframe >= 0)
      f.T_w_c = orthonormalised(map.keyframe(f.reference_keyframe).T_w_c * f.T_ref_c);
}

FusionReport fuse_final_map(const Map& map, const std::vector<TrackedFrame>& tracked,
                            KeyframeSamples samples, const TumSequence& sequence,
                            const Settings& settings, const std::filesystem::path& ply_path,
                            const ProgressCallback& progress) {
  if (!settings.map.enabled) return {};
  std::vector<FusionFrame> keyframes;
  for (size_t k = 0; k < map.keyframes().size(); ++k) {
    const Keyframe& keyframe = map.keyframe(int(k));
    if (keyframe.culled) continue;  // left out, as from global BA and the loop pass
    keyframes.push_back({keyframe.frame_index, keyframe.T_w_c, samples.of(k)});
  }
  std::vector<FusionFrame> frames;
  if (settings.map.frame_step <= 0) {
    frames = keyframes;
  } else {
    for (size_t i = 0; i < tracked.size(); i += size_t(settings.map.frame_step))
      if (!tracked[i].lost) frames.push_back({tracked[i].index, tracked[i].T_w_c, nullptr});
  }
  if (frames.empty()) return {};
  // The keyframes' centres beside the map, so that a viewer shows both.
  for (FusionFrame& k : keyframes) k.samples.reset();
  write_camera_poses_ply(ply_path.parent_path() / "keyframe_centres.ply", keyframes);
  samples = KeyframeSamples();  // `frames` holds the samples now: fusion frees each once fused
  return fuse_map(sequence, std::move(frames), settings.map, ply_path,
                  ply_path.parent_path() / "mesh.ply", [&](size_t done, size_t total) {
                    if (progress) progress("map", done, total);
                  });
}

}  // namespace slamkit
