#include "loop/loop_verification.h"

#include <gtest/gtest.h>

#include "pipeline/pipeline_test_support.h"
#include "pipeline/run_pipeline.h"

namespace slamkit {
namespace {

// The front end's map of the synthetic loop (200 frames once round the desk, ending on the
// first pose), its first and last keyframes at the same place.
struct LoopMap {
  TumSequence sequence;
  RunResult run;
};

const LoopMap& loop_map() {
  static const LoopMap* map = [] {
    const TumSequence seq =
        TumSequence::open(test::synthetic_sequence(synth::Preset::kLoop, 200));
    return new LoopMap{seq, track_sequence(seq, front_end_only(Settings{}))};
  }();
  return *map;
}

Eigen::Isometry3d true_pose(const TumSequence& seq, double stamp) {
  const Trajectory& gt = *seq.groundtruth();
  return gt.pose(*gt.nearest(stamp, 1e-6));
}

TEST(LoopVerification, AcceptsTheTrueRevisitWithItsRelativePose) {
  const LoopMap& m = loop_map();
  const Map& map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  const LoopVerification v = verify_loop(map, last, 0, m.sequence.camera(), Settings{}.matcher,
                                         Settings{}.tracking.ransac, {});
  std::printf("loop: %d matches, %d inliers, pose error %.4f m, %s\n", v.matches, v.inliers,
              v.pose_error, v.reason.c_str());
  ASSERT_TRUE(v.accepted) << v.reason;
  EXPECT_GE(v.matches, 50);
  const Eigen::Isometry3d truth = true_pose(m.sequence, map.keyframe(last).stamp).inverse() *
                                  true_pose(m.sequence, map.keyframe(0).stamp);
  EXPECT_LT((v.T_keyframe_candidate.translation() - truth.translation()).norm(), 0.02);
  EXPECT_LT(Eigen::AngleAxisd(v.T_keyframe_candidate.linear().transpose() * truth.linear()).angle(),
            1.0 * M_PI / 180);
}

TEST(LoopVerification, KappaRejectsAPoseFarFromTheEstimate) {
  const LoopMap& m = loop_map();
  // The current keyframe's estimate 2 m off, as when the same-looking place is elsewhere:
  // its own depth still measures the same relative pose to the candidate.
  Map map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  Eigen::Isometry3d moved = map.keyframe(last).T_w_c;
  moved.translation() += Eigen::Vector3d(2, 0, 0);
  map.set_keyframe_pose(last, moved);
  const LoopVerification v = verify_loop(map, last, 0, m.sequence.camera(), Settings{}.matcher,
                                         Settings{}.tracking.ransac, {});
  EXPECT_FALSE(v.accepted);
  EXPECT_NEAR(v.pose_error, 2.0, 0.05);
  EXPECT_NE(v.reason.find("kappa"), std::string::npos) << v.reason;
}

TEST(LoopVerification, TheFarSideOfTheLoopIsNoLoop) {
  const LoopMap& m = loop_map();
  const Map& map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  const LoopVerification v = verify_loop(map, last, last / 2, m.sequence.camera(),
                                         Settings{}.matcher, Settings{}.tracking.ransac, {});
  std::printf("far side: %d matches, %s\n", v.matches, v.reason.c_str());
  EXPECT_FALSE(v.accepted);
}

}  // namespace
}  // namespace slamkit
