#pragma once
// `slamkit run`: the whole batch in order (docs/method.md#architecture), one line a stage.
#include <filesystem>
#include <string>

#include "pipeline/batch_engine.h"

namespace slamkit {

// Prepare and track (local BA at each keyframe), the loop pass (with `vocabulary`, or one
// trained on the keyframes), global BA, re-anchor every frame, fuse the map (out/map.ply),
// write the run folder. Evaluation, which needs nothing of the engine, is the caller's (eval/).
RunResult run_batch(const TumSequence& sequence, const Settings& settings,
                    const std::filesystem::path& out, const std::string& sequence_name,
                    const ProgressCallback& progress = {}, const Vocabulary* vocabulary = nullptr);

// The settings of the front end alone (`slamkit track`): no local or global BA, no loop
// pass, no frame refinement, no map.
Settings front_end_only(Settings settings);

}  // namespace slamkit
