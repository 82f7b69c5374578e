#pragma once
// The batch engine (docs/method.md#architecture): reads a whole sequence, prepares frames in
// parallel chunks (the next chunk while the current one is tracked), tracks them in order with
// the map's upkeep and local BA at each keyframe, then runs the global stages over the whole
// map.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/settings/settings.h"
#include "core/trajectory.h"
#include "fusion/keyframe_samples.h"
#include "fusion/map_fusion.h"
#include "io/tum_sequence.h"
#include "loop/loop_pass.h"
#include "map/map.h"
#include "mapping/local_mapper.h"
#include "tracking/tracked_frame.h"

namespace slamkit {

struct FrameTiming {
  double decode_ms = 0, features_ms = 0, window_code_ms = 0;  // parallel stage, per frame
  double mapping_ms = 0;  // keyframe insertion and local BA (keyframes only)
};

// Wall time of each stage, seconds.
struct StageTimes {
  double prepare = 0;   // parallel stage, summed over chunks (overlaps tracking)
  double track = 0;     // tracking and mapping, local BA included
  double local_ba = 0;  // local BA solving, beside tracking (or inside it with one thread)
  double loops = 0;     // the loop pass: vocabulary, detection, correction
  double global_ba = 0;
  double refine = 0;  // frame refinement
  double fusion = 0;
  double write = 0;
  double total = 0;  // decode to the last file written
};

struct RunResult {
  std::vector<TrackedFrame> frames;              // one per associated frame, in order; final poses
  std::vector<FrameTiming> timing;               // one per frame
  std::vector<Eigen::Isometry3d> tracked_poses;  // as tracking produced them, per frame
  std::vector<MappingReport> keyframe_reports;   // one per keyframe
  Map map;
  // The keyframes' samples for the map's fusion (map.keyframe_cache_mb), until fused.
  KeyframeSamples keyframe_samples;
  LoopPassReport loop_pass;  // ran = false unless the loop pass ran
  MapAdjustment global_ba;   // empty unless the global BA ran
  bool global_ba_run = false;
  int refined_frames = 0;  // frames whose pose frame refinement solved again
  FusionReport fusion;  // frames == 0 unless the map was fused
  StageTimes seconds;
  // Process CPU seconds of each stage, every thread counted. Preparation and local BA run
  // beside tracking, so `track` holds theirs and `prepare` and `local_ba` stay 0.
  StageTimes cpu_seconds;
  double peak_rss_mb = 0;  // the process's most resident memory up to the map's writing
  int threads = 1;
  LostFrames lost_frames = LostFrames::kOmit;  // whether trajectories hold the lost frames

  Trajectory trajectory() const;          // final poses
  Trajectory tracked_trajectory() const;  // before the back end's corrections reach frames
  Trajectory keyframe_trajectory() const;
};

// Called with (stage, done, total): stage is "track", "global BA" or "map".
using ProgressCallback = std::function<void(const std::string&, size_t, size_t)>;

// The stages of a run, in order (run_pipeline.h runs them). Each takes what it reads and
// returns what it makes; the map is the one thing they share and change.

// Prepare, track (with local BA at each keyframe, if enabled): the front end's run.
// Throws InputError for unreadable frames (naming the file).
RunResult track_sequence(const TumSequence& sequence, const Settings& settings,
                         const ProgressCallback& progress = {});

// The loop pass (docs/method.md#loop-closing) on the tracked map is loop/loop_pass.h's
// close_loops: keyframe poses and points move; the frames follow at reanchor_frames.

// Global BA over every keyframe and point (keyframe 0 fixed); nullopt when it is off or the
// map has fewer than 2 keyframes.
std::optional<MapAdjustment> adjust_globally(Map& map, const Camera& camera,
                                             const Settings& settings);

// Every frame takes its reference keyframe's final pose composed with its pose relative to
// that keyframe when it was tracked (keyframes take their own); a culled keyframe first takes
// its parent's, as ORB-SLAM2 writes its trajectory.
void reanchor_frames(Map& map, std::vector<TrackedFrame>& frames);

// The fused map of the final poses, written to `ply_path` (settings.map), with
// keyframe_centres.ply beside it; frames == 0 when the map is not fused. Takes the samples,
// which are freed once fused.
FusionReport fuse_final_map(const Map& map, const std::vector<TrackedFrame>& frames,
                            KeyframeSamples samples, const TumSequence& sequence,
                            const Settings& settings, const std::filesystem::path& ply_path,
                            const ProgressCallback& progress = {});

}  // namespace slamkit
