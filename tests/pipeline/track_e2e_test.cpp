// End-to-end tracking: the front end over real TUM frames and synthetic sequences with exact
// groundtruth, judged by the project's own evaluator (the acceptance numbers).
#include <gtest/gtest.h>

#include "datasets/synth/trajectory_presets.h"
#include "io/trajectory_io.h"
#include "pipeline/batch_engine.h"
#include "pipeline/run_output.h"
#include "pipeline/run_pipeline.h"
#include "pipeline_test_support.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

// The front end alone, as `slamkit track` runs it.
RunResult track_front_end(const TumSequence& seq, const Settings& settings = {}) {
  return track_sequence(seq, front_end_only(settings));
}

using test::ate_rmse;
using test::count_lost;
using test::file_text;

fs::path synthetic(synth::Preset preset, int frames) {
  return test::synthetic_sequence(preset, frames);
}

TEST(Track, Fr2DeskFirst50WithinOrbSlam2Accuracy) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  SequenceOptions options;
  options.depth_scale = 5208;  // ORB-SLAM2's Freiburg 2 depth correction, as its result used
  const TumSequence seq = TumSequence::open(folder, options);
  const RunResult result = track_front_end(seq);
  EXPECT_EQ(count_lost(result), 0);
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("fr2/desk first 50, depth scale 5208: ATE RMSE %.4f m\n", rmse);
  EXPECT_LE(rmse, 0.006);
}

TEST(Track, Fr2DeskFirst50WithTheBenchmarkDepthScale) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence seq = TumSequence::open(folder);
  const RunResult result = track_front_end(seq);
  EXPECT_EQ(count_lost(result), 0);
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("fr2/desk first 50, depth scale 5000: ATE RMSE %.4f m\n", rmse);
  // The uncorrected 4% depth bias shows as scale error that a rigid alignment cannot remove.
  EXPECT_LE(rmse, 0.012);
}

TEST(Track, Fr1DeskFastMotionDistortedCamera) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg1_desk_9frames");
  const TumSequence seq = TumSequence::open(folder);
  const RunResult result = track_front_end(seq);
  EXPECT_EQ(count_lost(result), 0);
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("fr1/desk 9 frames: ATE RMSE %.4f m\n", rmse);
  EXPECT_LE(rmse, 0.004);
}

TEST(Track, SameTrajectoryFileWithOneAndTwoThreads) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence seq = TumSequence::open(folder);
  const fs::path dir = test::temp_dir("determinism");
  for (int threads : {1, 2}) {
    Settings settings;
    settings.pipeline.threads = threads;
    settings.pipeline.chunk_frames = 7 * threads;  // chunking must not matter either
    write_run_outputs(dir / std::to_string(threads), "fr2", seq.camera(), settings,
                      track_front_end(seq, settings));
  }
  const std::string one = file_text(dir / "1" / "trajectory.txt");
  EXPECT_GT(one.size(), 1000u);
  EXPECT_EQ(one, file_text(dir / "2" / "trajectory.txt"));
  EXPECT_EQ(file_text(dir / "1" / "keyframes.txt"), file_text(dir / "2" / "keyframes.txt"));
}

TEST(Track, SyntheticDeskCentimetreAccurateNoFrameLost) {
  const TumSequence seq = TumSequence::open(synthetic(synth::Preset::kDesk, 600));
  const RunResult result = track_front_end(seq);
  EXPECT_EQ(count_lost(result), 0);
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("synthetic desk 600: ATE RMSE %.4f m\n", rmse);
  EXPECT_LE(rmse, 0.01);
}

// 600 frames, the generator's default: the preset is scripted by phase, so fewer frames
// would make it faster than hand-held (300 frames peak at 2.7 m/s and 240 deg/s). Tracked
// with 1 and 2 threads: dense alignment's sums are taken in fixed blocks, so the trajectory
// file must not change by a byte.
TEST(Track, LowTextureWallCarriedByPointToPlaneSameWithOneAndTwoThreads) {
  constexpr int kFrames = 600;
  const TumSequence seq = TumSequence::open(synthetic(synth::Preset::kLowTexture, kFrames));
  const fs::path dir = test::temp_dir("lowtexture_threads");
  RunResult result;
  for (int threads : {1, 2}) {
    Settings settings;
    settings.pipeline.threads = threads;
    result = track_front_end(seq, settings);
    write_run_outputs(dir / std::to_string(threads), "lowtexture", seq.camera(), settings, result);
  }
  EXPECT_EQ(file_text(dir / "1" / "trajectory.txt"), file_text(dir / "2" / "trajectory.txt"));
  // The camera faces the plain corner from 32% to 72% of the sequence (trajectory_presets.cpp):
  // inside that stretch there are too few features for the closed form.
  const size_t wall_begin = size_t(0.35 * kFrames), wall_end = size_t(0.70 * kFrames);
  int dense_on_wall = 0;
  for (size_t i = wall_begin; i < wall_end; ++i)
    dense_on_wall += result.frames[i].solver == PoseSolver::kPointToPlane;
  std::printf("lowtexture: %d of %zu wall frames by point-to-plane, %d lost\n", dense_on_wall,
              wall_end - wall_begin, count_lost(result));
  EXPECT_EQ(dense_on_wall, int(wall_end - wall_begin));
  EXPECT_EQ(count_lost(result), 0);
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("lowtexture: ATE RMSE %.4f m\n", rmse);
  EXPECT_LT(rmse, 0.03);
}

TEST(Track, JerkWhipIsTrackedThroughout) {
  // The whip (4.6 m/s, 610 deg/s for two frames) is real motion the features support.
  const TumSequence seq = TumSequence::open(synthetic(synth::Preset::kJerk, 120));
  const RunResult result = track_front_end(seq);
  EXPECT_EQ(count_lost(result), 0);
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("jerk: ATE RMSE %.4f m\n", rmse);
  EXPECT_LT(rmse, 0.003);
}

TEST(Track, JerkUnderSpeedLimitsAloneIsBridgedRecoveredAndOmitted) {
  constexpr int kFrames = 120;
  const TumSequence seq = TumSequence::open(synthetic(synth::Preset::kJerk, kFrames));
  Settings settings;
  settings.tracking.failure.trusted_inliers = 0;  // no pose may outrun the limits
  RunResult result = track_front_end(seq, settings);
  const int whip = synth::jerk_whip_frame(kFrames);
  int first_lost = -1, last_lost = -1;
  for (const TrackedFrame& f : result.frames)
    if (f.lost) {
      if (first_lost < 0) first_lost = int(f.index);
      last_lost = int(f.index);
      EXPECT_EQ(f.solver, PoseSolver::kMotionModel);
    }
  const std::vector<std::string> report = describe_failures(result);
  for (const std::string& line : report) std::printf("jerk: %s\n", line.c_str());
  ASSERT_GE(first_lost, 0) << "the whip was not detected";
  EXPECT_GE(first_lost, whip);
  EXPECT_LE(first_lost, whip + 2);
  EXPECT_LE(last_lost - first_lost + 1, 5) << "recovery takes more than 5 frames";
  ASSERT_EQ(report.size(), 1u);
  EXPECT_NE(report[0].find("recovered"), std::string::npos);
  // Lost frames leave the trajectory by default (as ORB-SLAM2's), or hold the model's guess.
  const int lost = count_lost(result);
  EXPECT_EQ(result.trajectory().size(), size_t(kFrames - lost));
  result.lost_frames = LostFrames::kMotionModel;
  EXPECT_EQ(result.trajectory().size(), size_t(kFrames));
  // After recovery the trajectory is sound again.
  EXPECT_LT(ate_rmse(*seq.groundtruth(), result.trajectory()), 0.05);
}

TEST(Track, KinectJerkIsReacquiredFromTheMapAfterTheWhip) {
  // Through the kinect sensor the whip's frames are blurred past matching and lost. The
  // frames after it match a keyframe by descriptor too sparsely to be judged alone (about 40
  // matches): their pose seeds a projection search of the map, which re-acquires the frame.
  // Without that, 17 frames were lost and the ATE was 0.21 m; with it, 2 and 0.043 m, most of
  // which is the first re-acquired frame's (0.39 m off, from 54 inliers).
  constexpr int kFrames = 120;
  const TumSequence seq = TumSequence::open(test::synthetic_sequence(synth::Preset::kJerk, kFrames,
                                                                     /*kinect=*/true));
  const RunResult result = track_front_end(seq);
  const int whip = synth::jerk_whip_frame(kFrames);
  for (const TrackedFrame& f : result.frames) {
    if (f.lost) {
      EXPECT_GE(int(f.index), whip) << "lost before the whip";
      EXPECT_LE(int(f.index), whip + 3) << "not re-acquired after the whip";
    }
    // A frame tried twice reports the second attempt throughout (its inliers are a subset of
    // its matches), not the first's inliers beside the second's matches.
    EXPECT_LE(f.inliers, f.matches) << "frame " << f.index << ": " << f.failure;
  }
  const double rmse = ate_rmse(*seq.groundtruth(), result.trajectory());
  std::printf("kinect jerk: %d lost, ATE RMSE %.4f m\n", count_lost(result), rmse);
  EXPECT_LT(rmse, 0.06);
}

TEST(Track, KinectLoopStartingAtSpeedIsTrackedFromTheFirstFrames) {
  // The loop starts at 2.4 rad/s: frame 1 has no velocity to predict it by, and under the
  // rolling shutter the projection search from frame 0's pose fails. Re-acquired against the
  // map within the frame, as ORB-SLAM2 falls back on its reference keyframe, it is tracked;
  // re-acquired only at the next frame, every other frame of the first 16 was lost. Only the
  // first 24 frames of the 200-frame motion are rendered: the speed is the 200-frame loop's.
  const TumSequence seq = TumSequence::open(test::synthetic_sequence(
      synth::Preset::kLoop, 200, /*kinect=*/true, /*seed=*/2, /*first_frames=*/24));
  const RunResult result = track_front_end(seq);
  ASSERT_GE(result.frames.size(), 20u);
  for (const TrackedFrame& f : result.frames)
    if (f.index < 20) {
      EXPECT_FALSE(f.lost) << "frame " << f.index << ": " << f.failure;
    }
}

}  // namespace
}  // namespace slamkit
