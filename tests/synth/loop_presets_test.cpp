// The presets made for loop closing: what they revisit, and the look-alike places.
#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/core.hpp>

#include "datasets/synth/multi_room_layouts.h"
#include "datasets/synth/renderer.h"
#include "datasets/synth/revisits.h"
#include "datasets/synth/sequence_writer.h"
#include "synth/shared_room.h"

namespace slamkit::synth {
namespace {

Eigen::Isometry3d shifted(const Eigen::Isometry3d& T_w_c, const Eigen::Vector3d& offset) {
  return Eigen::Translation3d(offset) * T_w_c;
}

double mean_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff;
  cv::absdiff(a, b, diff);
  return cv::mean(diff.reshape(1))[0];
}

TEST(LoopPresets, LoopAndLongEndByRevisitingTheirStart) {
  for (const auto& [preset, frames] : {std::pair{Preset::kLoop, 600}, {Preset::kLong, 2000}}) {
    const std::vector<RevisitRange> revisits = true_revisits(make_trajectory(preset, frames, 1));
    const int last = frames - 1;  // a structured binding cannot be captured in C++17 (clang)
    const auto last_to_first = std::find_if(revisits.begin(), revisits.end(), [&](auto& r) {
      return r.later == last && r.first == 0;
    });
    EXPECT_NE(last_to_first, revisits.end()) << preset_name(preset);
  }
}

TEST(LoopPresets, LookalikeTrulyRevisitsOnlyTheFirstRoom) {
  const auto poses = make_trajectory(Preset::kLookalike, 900, 1);
  const std::vector<RevisitRange> revisits = true_revisits(poses);
  ASSERT_FALSE(revisits.empty());  // the return to the first place
  for (const RevisitRange& r : revisits) {
    EXPECT_LT(poses[r.later].translation().x(), 0) << r.later << " is in the twin room";
    EXPECT_LT(poses[r.first].translation().x(), 0) << r.first << " is in the twin room";
  }
}

TEST(LoopPresets, LookalikeVisitsTwoPlacesThatLookTheSameMetresApart) {
  const auto poses = make_trajectory(Preset::kLookalike, 900, 1);
  const Eigen::Isometry3d place = poses[0], twin = shifted(place, kTwinOffset);
  // The camera comes to the twin view, more than 3 m from the first...
  double closest = 1e9;
  for (const auto& T_w_c : poses)
    closest = std::min(closest, (T_w_c.translation() - twin.translation()).norm());
  EXPECT_LT(closest, 0.03);
  EXPECT_GT(kTwinOffset.norm(), 3.0);
  // ...where it sees what it saw there: the same image and depth (same sensor noise), while
  // a view moved by 2 cm differs plainly.
  const SyntheticScene& scene = test::shared_scene(Preset::kLookalike);
  const Camera camera = synthetic_camera();
  const SensorModel sensor;
  const RenderedFrame a = render_frame(scene, camera, place, sensor, 1, 0);
  const RenderedFrame b = render_frame(scene, camera, twin, sensor, 1, 0);
  const RenderedFrame moved =
      render_frame(scene, camera, shifted(place, Eigen::Vector3d(0.02, 0, 0)), sensor, 1, 0);
  // Not 0: the twin's pixels are rendered 3 m away in floating point (0.18 grey levels with
  // gcc -O3, 0.23 with clang -O1).
  EXPECT_LT(mean_difference(a.bgr, b.bgr), 0.5);
  EXPECT_LT(mean_difference(a.depth, b.depth), 1.0);  // units of 0.2 mm
  EXPECT_GT(mean_difference(a.bgr, moved.bgr), 5.0);
}

}  // namespace
}  // namespace slamkit::synth
