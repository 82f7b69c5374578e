#pragma once
// The loop pass of the batch (after tracking, before global BA: docs/method.md#architecture;
// docs/method.md#loop-closing): every keyframe, in order, queries the keyframes before it by
// bag of words; the candidates that pass the paper's checks become loop edges, and the
// essential graph spreads their correction over the map before the global BA refines it.
#include <vector>

#include "core/camera.h"
#include "core/settings/settings.h"
#include "loop/loop_verification.h"
#include "loop/vocabulary.h"
#include "map/map.h"
#include "optimization/map_pose_graph.h"

namespace slamkit {

// One candidate as judged (a row of loops.csv).
struct LoopDecision {
  int keyframe = -1;
  int candidate = -1;
  double score = 0;      // L1 bag-of-words score with the keyframe
  double min_score = 0;  // the lowest score of the keyframe's covisible neighbours
  int consistent = 0;    // the candidate's neighbours that are candidates too
  bool verified = false;  // geometric checks run (consistent, among the best max_verified)
  LoopVerification check;
};

struct LoopPassReport {
  bool ran = false;
  int keyframes = 0;
  size_t vocabulary_words = 0;
  std::vector<LoopDecision> decisions;
  std::vector<LoopConstraint> loops;  // the accepted ones
  // Solved when loops were found and corrected (some loop's gap >= settings.min_correction).
  PoseGraphReport correction;
  int fused_points = 0;  // loop fusion after the correction (loop_fusion.h)
  double vocabulary_seconds = 0, detection_seconds = 0, correction_seconds = 0;
};

// Detects loops among the map's keyframes and corrects the map with them. `vocabulary` null:
// one is trained on the keyframes' own descriptors (settings.vocabulary) when
// settings.loop.train_on_sequence, else the pass does not run.
LoopPassReport close_loops(Map& map, const Camera& camera, const Settings& settings,
                           const Vocabulary* vocabulary);

}  // namespace slamkit
