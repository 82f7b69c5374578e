#include "datasets/synth/trajectory_presets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/error.h"
#include "core/pose.h"
#include "datasets/synth/multi_room_layouts.h"
#include "synth/shared_room.h"

namespace slamkit::synth {
namespace {

struct Step {
  double translation, rotation_deg;
};

std::vector<Step> steps(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Step> out;
  for (size_t i = 1; i < poses.size(); ++i) {
    const Eigen::Isometry3d delta = poses[i - 1].inverse() * poses[i];
    out.push_back({delta.translation().norm(), rotation_angle(delta) * 180.0 / M_PI});
  }
  return out;
}

TEST(TrajectoryPresets, LookAtPutsTheTargetOnTheOpticalAxisWithTheImageUpright) {
  const Eigen::Vector3d eye(1, 2, 1.5), target(0, 0, 0.7);
  const Eigen::Isometry3d T_w_c = look_at(eye, target);
  const Eigen::Vector3d target_c = T_w_c.inverse() * target;
  EXPECT_NEAR(target_c.x(), 0, 1e-12);
  EXPECT_NEAR(target_c.y(), 0, 1e-12);
  EXPECT_GT(target_c.z(), 0);
  // Image y (down) points against world z (up); image x is horizontal.
  EXPECT_LT(T_w_c.linear().col(1).z(), 0);
  EXPECT_NEAR(T_w_c.linear().col(0).z(), 0, 1e-12);
  EXPECT_NEAR(T_w_c.linear().determinant(), 1, 1e-12);
}

TEST(TrajectoryPresets, LoopEndsExactlyOnItsStartPose) {
  for (int frames : {20, 600}) {
    const auto poses = make_trajectory(Preset::kLoop, frames, 1);
    EXPECT_TRUE(poses.back().isApprox(poses.front(), 0.0)) << frames;
    // ...after going somewhere: halfway it is across the desk, facing the other way.
    EXPECT_GT((poses[frames / 2].translation() - poses[0].translation()).norm(), 1.9);
    EXPECT_GT(rotation_angle(poses[0].inverse() * poses[frames / 2]), 120 * M_PI / 180);
  }
}

TEST(TrajectoryPresets, JerkHasOneWhipMuchLargerThanEveryOtherStep) {
  const int frames = 600;
  const auto s = steps(make_trajectory(Preset::kJerk, frames, 1));
  const int whip = jerk_whip_frame(frames);
  double calm_rotation = 0, calm_translation = 0;
  for (int i = 0; i < int(s.size()); ++i) {
    if (i == whip || i == whip + 1) {
      EXPECT_GT(s[i].rotation_deg, 15) << "step " << i;
      EXPECT_LT(s[i].rotation_deg, 25) << "step " << i;
      EXPECT_GT(s[i].translation, 0.10) << "step " << i;
      EXPECT_LT(s[i].translation, 0.20) << "step " << i;
    } else {
      calm_rotation = std::max(calm_rotation, s[i].rotation_deg);
      calm_translation = std::max(calm_translation, s[i].translation);
    }
  }
  EXPECT_LT(calm_rotation, 15.0 / 5);  // 30 Hz: every other step is a fifth of the whip
  EXPECT_LT(calm_translation, 0.10 / 5);
}

TEST(TrajectoryPresets, DeskMovesAtHandHeldSpeeds) {
  const auto s = steps(make_trajectory(Preset::kDesk, 600, 1));
  double metres = 0, degrees = 0;
  for (const Step& step : s) metres += step.translation, degrees += step.rotation_deg;
  const double seconds = s.size() / kFrameRate;
  EXPECT_GT(metres / seconds, 0.3);
  EXPECT_LT(metres / seconds, 0.5);
  EXPECT_GT(degrees / seconds, 20);
  EXPECT_LT(degrees / seconds, 40);
}

TEST(TrajectoryPresets, SameSeedSamePathOtherSeedOtherShake) {
  for (const std::string& name : preset_names()) {
    const Preset preset = parse_preset(name);
    const auto a = make_trajectory(preset, 50, 3), b = make_trajectory(preset, 50, 3);
    const auto c = make_trajectory(preset, 50, 4);
    for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i].isApprox(b[i], 0.0)) << name;
    // The shake differs by millimetres, not more.
    const double shift = (a[25].translation() - c[25].translation()).norm();
    EXPECT_GT(shift, 1e-5) << name;
    EXPECT_LT(shift, 0.03) << name;
  }
}

TEST(TrajectoryPresets, EveryPresetKeepsTheCameraInFreeSpaceAtHandHeldSpeeds) {
  for (const std::string& name : preset_names()) {
    const Preset preset = parse_preset(name);
    const int frames = preset == Preset::kLong ? 2000 : 600;
    const auto poses = make_trajectory(preset, frames, 1);
    const SyntheticScene& scene = test::shared_scene(preset);
    double clearance = 1e9;
    for (const auto& T_w_c : poses)
      clearance = std::min(clearance, scene.signed_distance(T_w_c.translation()));
    EXPECT_GT(clearance, 0.15) << name << ": the camera comes this close to a surface";
    if (preset == Preset::kJerk) continue;  // its whip is the point
    for (const Step& step : steps(poses)) {
      ASSERT_LT(step.translation * kFrameRate, 2.0) << name << " m/s";
      ASSERT_LT(step.rotation_deg * kFrameRate, 150) << name << " deg/s";
    }
  }
}

TEST(TrajectoryPresets, LoopAt150FramesStaysWithinTheTrackersFailureLimits) {
  // The tracker's failure check: 3 m/s and 200 deg/s (loop tests run 150 and 200 frames).
  for (const Step& step : steps(make_trajectory(Preset::kLoop, 150, 1))) {
    ASSERT_LT(step.translation * kFrameRate, 2.0);
    ASSERT_LT(step.rotation_deg * kFrameRate, 160);
  }
}

TEST(TrajectoryPresets, LongGoesThroughBothRoomsAndBackToItsStart) {
  const auto poses = make_trajectory(Preset::kLong, 2000, 1);
  double west = 1e9, east = -1e9;
  for (const auto& T_w_c : poses) {
    west = std::min(west, T_w_c.translation().x());
    east = std::max(east, T_w_c.translation().x());
  }
  EXPECT_LT(west, kDoorwayX - 3.5);  // deep in the first room...
  EXPECT_GT(east, kDoorwayX + 3.0);  // ...and in the second
  EXPECT_LT((poses.back().translation() - poses.front().translation()).norm(), 0.5);
  EXPECT_LT(rotation_angle(poses.front().inverse() * poses.back()), 5 * M_PI / 180);
}

TEST(TrajectoryPresets, BadArgumentsAreInputErrors) {
  EXPECT_THROW(parse_preset("spiral"), InputError);
  EXPECT_THROW(make_trajectory(Preset::kDesk, 1, 1), InputError);
  EXPECT_EQ(preset_name(parse_preset("lowtexture")), "lowtexture");
}

TEST(ContinuousTrajectory, AgreesWithTheFramesAtFrameTimesAndMovesSmoothlyBetween) {
  for (const std::string& name : preset_names()) {
    const Preset preset = parse_preset(name);
    const int frames = 90;
    const std::vector<Eigen::Isometry3d> poses = make_trajectory(preset, frames, 3);
    const ContinuousTrajectory trajectory(preset, frames, 3);
    for (int i = 0; i < frames; ++i) {
      const Eigen::Isometry3d delta = poses[i].inverse() * trajectory.pose(i / kFrameRate);
      EXPECT_LT(delta.translation().norm(), 1e-9) << name << " frame " << i;
      EXPECT_LT(rotation_angle(delta), 1e-9) << name << " frame " << i;
    }
    // Half-way between two frames the pose lies between theirs; jerk's whip included.
    for (int i = 0; i + 1 < frames; ++i) {
      const Eigen::Isometry3d mid = trajectory.pose((i + 0.5) / kFrameRate);
      const double step = (poses[i].translation() - poses[i + 1].translation()).norm();
      EXPECT_LE((mid.translation() - poses[i].translation()).norm(), step + 1e-6)
          << name << " frame " << i;
    }
    // Sensors sample before the first frame (a depth stream ahead of the colour one).
    EXPECT_TRUE(trajectory.pose(-0.02).matrix().allFinite()) << name;
  }
}

}  // namespace
}  // namespace slamkit::synth
