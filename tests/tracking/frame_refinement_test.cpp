#include "tracking/frame_refinement.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <random>

namespace slamkit {
namespace {

constexpr int kPoints = 200;

Camera pinhole() {
  Camera c = Camera::freiburg3();  // no lens distortion
  c.readout_time = 0;
  return c;
}

Eigen::Isometry3d pose(double yaw_deg, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitY()).matrix();
  T.translation() = t;
  return T;
}

// A map of one keyframe observing kPoints points 1-3 m in front of the origin, spread over the
// image (the keyframe's keypoints are not read by the refinement).
Map map_of_points(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-0.5, 0.5), y(-0.4, 0.4), z(1.0, 3.0);
  Keyframe k;
  k.keypoints.resize(kPoints);
  k.undistorted.resize(kPoints, Eigen::Vector2d::Zero());
  k.depths.assign(kPoints, 0.0f);
  k.descriptors = cv::Mat(kPoints, 32, CV_8U, cv::Scalar(0));
  k.point_ids.assign(kPoints, -1);
  Map map;
  map.add_keyframe(std::move(k));
  for (int i = 0; i < kPoints; ++i) {
    const double depth = z(rng);
    map.add_point({x(rng) * depth, y(rng) * depth, depth}, 0, i);
  }
  return map;
}

// The frame as tracking would leave it: every point it sees matched at its exact projection
// from `truth` (with its depth), its pose `start`.
TrackedFrame frame_seeing(const Map& map, const Camera& camera, const Eigen::Isometry3d& truth,
                          const Eigen::Isometry3d& start) {
  TrackedFrame f;
  f.T_w_c = start;
  const Eigen::Isometry3d T_c_w = truth.inverse();
  for (int id = 0; id < map.num_point_ids(); ++id) {
    const Eigen::Vector3d p_c = T_c_w * map.point(id).p_w;
    const Eigen::Vector2d uv = camera.project(p_c);
    if (p_c.z() <= 0 || !camera.contains(uv)) continue;
    f.matched.push_back({id, float(uv.x()), float(uv.y()), float(p_c.z()), 1.0f});
  }
  return f;
}

double translation_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

TEST(FrameRefinement, RecoversTheTruePoseFromThePointsAsTheyAre) {
  const Camera camera = pinhole();
  const Map map = map_of_points(1);
  const Eigen::Isometry3d truth = pose(4, {0.05, -0.02, 0.10});
  // Tracked against points that have moved since: 8 mm and 0.3 degrees off.
  const Eigen::Isometry3d start = truth * pose(0.3, {0.008, 0.0, -0.004});
  std::vector<TrackedFrame> frames = {frame_seeing(map, camera, truth, start)};
  ASSERT_GT(frames[0].matched.size(), 150u);

  EXPECT_EQ(refine_frames(map, camera, MotionBaSettings{}, frames), 1);
  EXPECT_LT(translation_error(frames[0].T_w_c, truth), 1e-6);
  EXPECT_LT(Eigen::AngleAxisd(frames[0].T_w_c.linear().transpose() * truth.linear()).angle(),
            1e-7);
  EXPECT_TRUE(frames[0].matched.empty());  // released
}

TEST(FrameRefinement, FramesWithoutMatchesOrTooFewInliersKeepTheirPose) {
  const Camera camera = pinhole();
  const Map map = map_of_points(2);
  const Eigen::Isometry3d truth = pose(-3, {0.0, 0.03, 0.0});
  const Eigen::Isometry3d start = truth * pose(0.2, {0.005, 0.0, 0.0});
  TrackedFrame keyframe_like;  // a keyframe, a lost frame or one refinement was not given
  keyframe_like.T_w_c = start;
  TrackedFrame few = frame_seeing(map, camera, truth, start);
  few.matched.resize(size_t(MotionBaSettings{}.min_inliers - 1));
  std::vector<TrackedFrame> frames = {keyframe_like, few};

  EXPECT_EQ(refine_frames(map, camera, MotionBaSettings{}, frames), 0);
  for (const TrackedFrame& f : frames) EXPECT_TRUE(f.T_w_c.isApprox(start, 0));
}

TEST(FrameRefinement, PointsCulledSinceTrackingAreLeftOut) {
  // A culled point reads as an empty one at the world origin; the frame stands 1 m behind the
  // origin, so that such points lie in front of it, in view.
  const Camera camera = pinhole();
  const Eigen::Isometry3d truth = pose(2, {0.02, 0.0, -1.0});
  const Eigen::Isometry3d start = truth * pose(-0.2, {0.0, 0.006, 0.0});
  {
    // Every second match goes to a point culled since: the rest still give the true pose.
    Map map = map_of_points(3);
    std::vector<TrackedFrame> frames = {frame_seeing(map, camera, truth, start)};
    for (size_t i = 0; i < frames[0].matched.size(); i += 2)
      map.cull_point(frames[0].matched[i].point_id);
    EXPECT_EQ(refine_frames(map, camera, MotionBaSettings{}, frames), 1);
    EXPECT_LT(translation_error(frames[0].T_w_c, truth), 1e-6);
  }
  {
    // Every match but 5 goes to a point culled since: 5 cannot make a pose, so it stays.
    Map map = map_of_points(3);
    std::vector<TrackedFrame> frames = {frame_seeing(map, camera, truth, start)};
    for (size_t i = 5; i < frames[0].matched.size(); ++i)
      map.cull_point(frames[0].matched[i].point_id);
    EXPECT_EQ(refine_frames(map, camera, MotionBaSettings{}, frames), 0);
    EXPECT_TRUE(frames[0].T_w_c.isApprox(start, 0));
  }
}

TEST(FrameRefinement, SameResultForAnyThreadCount) {
  const Camera camera = pinhole();
  const Map map = map_of_points(4);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 1.0);
  std::vector<TrackedFrame> frames;
  for (int i = 0; i < 64; ++i) {
    const Eigen::Isometry3d truth = pose(0.2 * i, {0.002 * i, 0.0, 0.001 * i});
    TrackedFrame f = frame_seeing(map, camera, truth, truth * pose(0.1, {0.003, 0.0, 0.0}));
    for (MatchedKeypoint& m : f.matched) {  // 1 px of keypoint noise, different per frame
      m.u += float(noise(rng));
      m.v += float(noise(rng));
    }
    frames.push_back(f);
  }
  std::vector<TrackedFrame> one = frames, two = frames;
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const int moved_one = refine_frames(map, camera, MotionBaSettings{}, one);
  omp_set_num_threads(2);
  const int moved_two = refine_frames(map, camera, MotionBaSettings{}, two);
  omp_set_num_threads(threads);

  EXPECT_EQ(moved_one, 64);
  EXPECT_EQ(moved_two, 64);
  for (size_t i = 0; i < frames.size(); ++i)
    EXPECT_TRUE(one[i].T_w_c.matrix() == two[i].T_w_c.matrix()) << "frame " << i;
}

}  // namespace
}  // namespace slamkit
