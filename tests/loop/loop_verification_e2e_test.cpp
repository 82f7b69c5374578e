#include "loop/loop_verification.h"

#include <gtest/gtest.h>

#include "features/descriptor_matcher.h"
#include "loop/loop_map_fixture.h"
#include "loop/loop_neighbourhood.h"

namespace slamkit {
namespace {

// Every descriptor match of the two keyframes (the loop pass matches through the vocabulary).
LoopVerification verify(const Map& map, int keyframe, int candidate, const Camera& camera) {
  std::vector<KeypointPair> pairs;
  for (const cv::DMatch& m : match_descriptors(map.keyframe(keyframe).descriptors,
                                               map.keyframe(candidate).descriptors,
                                               Settings{}.matcher))
    pairs.push_back({m.queryIdx, m.trainIdx});
  return verify_loop(map, keyframe, candidate, pairs, camera, Settings{}.tracking.ransac,
                     Settings{}.tracking.motion_ba, LoopSettings{});
}

TEST(LoopVerification, AcceptsTheTrueRevisitWithItsRelativePose) {
  const test::LoopMap& m = test::loop_map();
  const Map& map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  const LoopVerification v = verify(map, last, 0, m.sequence.camera());
  std::printf("loop: %d matches, %d inliers, pose error %.4f m, %s\n", v.matches, v.inliers,
              v.pose_error, v.reason.c_str());
  ASSERT_TRUE(v.accepted) << v.reason;
  EXPECT_GE(v.matches, 50);
  EXPECT_GT(v.neighbourhood_inliers, v.inliers) << "the candidate's neighbours add matches";
  const Eigen::Isometry3d truth = test::true_pose(m.sequence, map.keyframe(last).stamp).inverse() *
                                  test::true_pose(m.sequence, map.keyframe(0).stamp);
  EXPECT_LT((v.T_keyframe_candidate.translation() - truth.translation()).norm(), 0.02);
  EXPECT_LT(Eigen::AngleAxisd(v.T_keyframe_candidate.linear().transpose() * truth.linear()).angle(),
            1.0 * M_PI / 180);
}

TEST(LoopVerification, KappaRejectsAPoseFarFromTheEstimate) {
  const test::LoopMap& m = test::loop_map();
  // The current keyframe's estimate 2 m off, as when the same-looking place is elsewhere:
  // its own depth still measures the same relative pose to the candidate.
  Map map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  const double drift = verify(map, last, 0, m.sequence.camera()).pose_error;
  Eigen::Isometry3d moved = map.keyframe(last).T_w_c;
  moved.translation() += Eigen::Vector3d(2, 0, 0);
  map.set_keyframe_pose(last, moved);
  const LoopVerification v = verify(map, last, 0, m.sequence.camera());
  EXPECT_FALSE(v.accepted);
  EXPECT_NEAR(v.pose_error, 2.0, drift + 0.01);  // the 2 m added to the tracking's own drift
  EXPECT_NE(v.reason.find("kappa"), std::string::npos) << v.reason;
}

TEST(LoopVerification, TheNeighbourhoodLinesUpOnlyWithTheTruePose) {
  const test::LoopMap& m = test::loop_map();
  const Map& map = m.run.map;
  const Camera& camera = m.sequence.camera();
  const int last = int(map.keyframes().size()) - 1;
  const LoopVerification v = verify(map, last, 0, camera);
  ASSERT_TRUE(v.accepted) << v.reason;
  const Eigen::Isometry3d T_w_keyframe = map.keyframe(0).T_w_c * v.T_keyframe_candidate.inverse();
  // 3 degrees about the camera's vertical: a far wall's pixels shift by about 27 px.
  const Eigen::Isometry3d turned =
      T_w_keyframe * Eigen::AngleAxisd(3 * M_PI / 180, Eigen::Vector3d::UnitY());
  const std::vector<bool> none(map.keyframe(last).keypoints.size(), false);
  const LoopSettings s;
  const auto right = match_loop_neighbourhood(map, last, 0, T_w_keyframe, none, camera,
                                              s.neighbourhood_radius, s.neighbourhood_max_distance);
  const auto wrong = match_loop_neighbourhood(map, last, 0, turned, none, camera,
                                              s.neighbourhood_radius, s.neighbourhood_max_distance);
  std::printf("neighbourhood matches: %zu with the measured pose, %zu turned 3 deg\n",
              right.size(), wrong.size());
  EXPECT_GE(int(right.size()), s.min_neighbourhood_inliers);
  EXPECT_LT(wrong.size() * 4, right.size());
  for (size_t i = 1; i < right.size(); ++i) EXPECT_LT(right[i - 1].keypoint, right[i].keypoint);

  // The keypoints already paired are left out.
  std::vector<bool> taken = none;
  for (const LoopPointMatch& match : right) taken[size_t(match.keypoint)] = true;
  const auto rest = match_loop_neighbourhood(map, last, 0, T_w_keyframe, taken, camera,
                                             s.neighbourhood_radius, s.neighbourhood_max_distance);
  EXPECT_LT(rest.size(), right.size());
  for (const LoopPointMatch& match : rest) EXPECT_FALSE(taken[size_t(match.keypoint)]);
}

TEST(LoopVerification, TooFewNeighbourhoodInliersIsNoLoop) {
  const test::LoopMap& m = test::loop_map();
  const Map& map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  const int found = verify(map, last, 0, m.sequence.camera()).neighbourhood_inliers;
  std::vector<KeypointPair> pairs;
  for (const cv::DMatch& d :
       match_descriptors(map.keyframe(last).descriptors, map.keyframe(0).descriptors,
                         Settings{}.matcher))
    pairs.push_back({d.queryIdx, d.trainIdx});
  LoopSettings strict;
  strict.min_neighbourhood_inliers = found + 1;
  const LoopVerification v =
      verify_loop(map, last, 0, pairs, m.sequence.camera(), Settings{}.tracking.ransac,
                  Settings{}.tracking.motion_ba, strict);
  EXPECT_FALSE(v.accepted);
  EXPECT_NE(v.reason.find("neighbourhood"), std::string::npos) << v.reason;
}

TEST(LoopVerification, TheFarSideOfTheLoopIsNoLoop) {
  const test::LoopMap& m = test::loop_map();
  const Map& map = m.run.map;
  const int last = int(map.keyframes().size()) - 1;
  const LoopVerification v = verify(map, last, last / 2, m.sequence.camera());
  std::printf("far side: %d matches, %s\n", v.matches, v.reason.c_str());
  EXPECT_FALSE(v.accepted);
}

}  // namespace
}  // namespace slamkit
