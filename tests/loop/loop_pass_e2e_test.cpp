#include "loop/loop_pass.h"

#include <gtest/gtest.h>

#include "loop/loop_map_fixture.h"
#include "loop/vocabulary_training.h"

namespace slamkit {
namespace {

// b's pose in a's frame by the groundtruth.
Eigen::Isometry3d true_relative(const test::LoopMap& m, int a, int b) {
  return test::true_pose(m.sequence, m.run.map.keyframe(a).stamp).inverse() *
         test::true_pose(m.sequence, m.run.map.keyframe(b).stamp);
}

TEST(LoopPass, FindsOnlyTrueRevisitsOnTheSyntheticLoopAndCorrectsTheMap) {
  const test::LoopMap& m = test::loop_map();
  Map map = m.run.map;
  Settings settings;
  const LoopPassReport report = close_loops(map, m.sequence.camera(), settings, nullptr);
  ASSERT_TRUE(report.ran);
  EXPECT_GT(report.vocabulary_words, 0u);
  ASSERT_FALSE(report.loops.empty()) << "the return to the start was not detected";
  // No false loop: each accepted edge measures the true relative pose, to the accuracy of the
  // map points near the start (the loop looks at walls 2-4 m away, where depth noise is cm).
  for (const LoopConstraint& loop : report.loops) {
    const Eigen::Isometry3d truth = true_relative(m, loop.keyframe, loop.loop_keyframe);
    std::printf("loop %d -> %d: %.2f m apart, measured to %.4f m\n", loop.keyframe,
                loop.loop_keyframe, truth.translation().norm(),
                (loop.T_keyframe_loop.translation() - truth.translation()).norm());
    EXPECT_LT((loop.T_keyframe_loop.translation() - truth.translation()).norm(), 0.03);
    EXPECT_LT(Eigen::AngleAxisd(loop.T_keyframe_loop.linear().transpose() * truth.linear()).angle(),
              1.5 * M_PI / 180);
  }
  EXPECT_TRUE(report.correction.solved);
  // Each judged candidate says why it was refused, and every accepted one passed the checks.
  for (const LoopDecision& d : report.decisions) {
    EXPECT_EQ(d.check.accepted, d.check.reason.empty()) << d.check.reason;
    if (d.check.accepted) {
      EXPECT_GE(d.consistent, Settings{}.loop.min_consistent_neighbours);
      EXPECT_GE(d.check.matches, 50);
      EXPECT_LT(d.check.pose_error, 1.0);
    }
  }
  // The last keyframe moved towards its true pose relative to the first.
  const auto error = [&](const Map& mp) {
    const Eigen::Isometry3d estimated = mp.keyframe(0).T_c_w * mp.keyframes().back().T_w_c;
    const Eigen::Isometry3d truth = test::true_pose(m.sequence, mp.keyframe(0).stamp).inverse() *
                                    test::true_pose(m.sequence, mp.keyframes().back().stamp);
    return (estimated.translation() - truth.translation()).norm();
  };
  std::printf("loop pass: %zu loops; first-to-last keyframe error %.4f -> %.4f m\n",
              report.loops.size(), error(m.run.map), error(map));
  EXPECT_LT(error(map), 0.5 * error(m.run.map));

  // Loop fusion: the last keyframe now observes points made at the start, so that global BA
  // ties the two ends together.
  const int last = int(map.keyframes().size()) - 1;
  EXPECT_EQ(m.run.map.keyframe(last).shared_points.count(0), 0u);
  EXPECT_GT(report.fused_points, 0);
  EXPECT_GT(map.keyframe(last).shared_points.count(0), 0u);
}

TEST(LoopPass, WithoutLoopFusionTheEndsShareNoPoints) {
  const test::LoopMap& m = test::loop_map();
  Map map = m.run.map;
  Settings settings;
  settings.loop.fuse_points = false;
  const LoopPassReport report = close_loops(map, m.sequence.camera(), settings, nullptr);
  ASSERT_TRUE(report.correction.solved);
  EXPECT_EQ(report.fused_points, 0);
  EXPECT_EQ(map.keyframe(int(map.keyframes().size()) - 1).shared_points.count(0), 0u);
}

TEST(LoopPass, GapsBelowMinCorrectionLeaveTheMapAsItIs) {
  const test::LoopMap& m = test::loop_map();
  Map map = m.run.map;
  Settings settings;
  settings.loop.min_correction = 1.0;  // above this loop's drift (about 0.2 m)
  const LoopPassReport report = close_loops(map, m.sequence.camera(), settings, nullptr);
  EXPECT_FALSE(report.loops.empty());
  EXPECT_FALSE(report.correction.solved);
  for (size_t k = 0; k < map.keyframes().size(); ++k)
    EXPECT_EQ(map.keyframe(int(k)).T_w_c.matrix(), m.run.map.keyframe(int(k)).T_w_c.matrix());
}

TEST(LoopPass, TrainingOnEverySecondKeyframeStillFindsTheLoop) {
  const test::LoopMap& m = test::loop_map();
  Map map = m.run.map;
  Settings settings;
  settings.loop.training_keyframe_step = 2;
  const LoopPassReport report = close_loops(map, m.sequence.camera(), settings, nullptr);
  // The tree is the one trained on keyframes 0, 2, 4, ... alone, smaller than on all of them.
  std::vector<cv::Mat> all, every_second;
  for (size_t k = 0; k < m.run.map.keyframes().size(); ++k) {
    all.push_back(m.run.map.keyframe(int(k)).descriptors);
    if (k % 2 == 0) every_second.push_back(all.back());
  }
  EXPECT_EQ(report.vocabulary_words, train_vocabulary(every_second, settings.vocabulary).word_count());
  EXPECT_LT(report.vocabulary_words, train_vocabulary(all, settings.vocabulary).word_count());
  EXPECT_FALSE(report.loops.empty());
  EXPECT_TRUE(report.correction.solved);
}

TEST(LoopPass, DisabledOrTooFewKeyframesDoesNotRun) {
  const test::LoopMap& m = test::loop_map();
  Map map = m.run.map;
  Settings off;
  off.loop.enabled = false;
  EXPECT_FALSE(close_loops(map, m.sequence.camera(), off, nullptr).ran);
  Settings few;
  few.loop.recent_keyframes = int(map.keyframes().size());
  EXPECT_FALSE(close_loops(map, m.sequence.camera(), few, nullptr).ran);
}

}  // namespace
}  // namespace slamkit
