#pragma once
// The front end's map of the synthetic loop (200 frames once round the desk, ending on the
// first pose), its first and last keyframes at the same place; built once per test process.
#include "pipeline/pipeline_test_support.h"
#include "pipeline/run_pipeline.h"

namespace slamkit::test {

struct LoopMap {
  TumSequence sequence;
  RunResult run;
};

inline const LoopMap& loop_map() {
  static const LoopMap* map = [] {
    const TumSequence seq =
        TumSequence::open(test::synthetic_sequence(synth::Preset::kLoop, 200));
    return new LoopMap{seq, track_sequence(seq, front_end_only(Settings{}))};
  }();
  return *map;
}

// The true pose of the frame at `stamp`.
inline Eigen::Isometry3d true_pose(const TumSequence& seq, double stamp) {
  const Trajectory& gt = *seq.groundtruth();
  return gt.pose(*gt.nearest(stamp, 1e-6));
}

}  // namespace slamkit::test
