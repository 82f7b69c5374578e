#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "features/batch_extraction.h"
#include "features/descriptor.h"
#include "features/descriptor_matcher.h"
#include "features/keypoint_grid.h"
#include "features/orb_extractor.h"
#include "features/projection_matcher.h"
#include "io/tum_sequence.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

bool same_features(const FrameFeatures& a, const FrameFeatures& b) {
  if (a.size() != b.size() || a.descriptors.size() != b.descriptors.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const cv::KeyPoint &p = a.keypoints[i], &q = b.keypoints[i];
    if (p.pt != q.pt || p.angle != q.angle || p.response != q.response || p.octave != q.octave) {
      return false;
    }
  }
  return std::memcmp(a.descriptors.data, b.descriptors.data, a.descriptors.total()) == 0;
}

bool same_matches(const std::vector<cv::DMatch>& a, const std::vector<cv::DMatch>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].queryIdx != b[i].queryIdx || a[i].trainIdx != b[i].trainIdx) return false;
  }
  return true;
}

TEST(BatchExtraction, SameResultsAtOneAndTwoThreads) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence sequence = TumSequence::open(folder);
  std::vector<cv::Mat> images;
  for (size_t i = 0; i < 6; ++i) images.push_back(sequence.load(i).rgb);
  const auto one = extract_orb_batch(images, sequence.camera(), OrbSettings{}, 1);
  const auto two = extract_orb_batch(images, sequence.camera(), OrbSettings{}, 2);
  ASSERT_EQ(one.size(), images.size());
  ASSERT_EQ(two.size(), images.size());
  for (size_t i = 0; i < images.size(); ++i) {
    EXPECT_TRUE(same_features(one[i], two[i])) << "frame " << i;
    EXPECT_TRUE(same_features(one[i], extract_orb(images[i], sequence.camera(), OrbSettings{})));
  }
  EXPECT_FALSE(same_features(one[0], one[5]));  // the comparison can tell frames apart
}

TEST(BatchExtraction, BadImageThrowsOutOfTheParallelLoop) {
  std::vector<cv::Mat> images = {cv::Mat(480, 640, CV_32F, cv::Scalar(0))};
  EXPECT_THROW(extract_orb_batch(images, Camera::freiburg3(), OrbSettings{}, 2),
               std::invalid_argument);
}

class ShiftedCopy : public ::testing::TestWithParam<MatcherBackend> {};

// Image B is image A moved by (7, -4) pixels: every correct match moves by that shift.
TEST_P(ShiftedCopy, MatchesFollowTheKnownShift) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const cv::Mat a = TumSequence::open(folder).load(0).rgb;
  cv::Mat b;
  const cv::Matx23d shift(1, 0, 7, 0, 1, -4);
  cv::warpAffine(a, b, shift, a.size());
  const Camera camera = Camera::freiburg3();
  const FrameFeatures fa = extract_orb(a, camera, OrbSettings{});
  const FrameFeatures fb = extract_orb(b, camera, OrbSettings{});
  MatcherSettings settings;
  settings.backend = GetParam();
  const std::vector<cv::DMatch> matches =
      match_descriptors(fa.descriptors, fb.descriptors, settings);
  int correct = 0;
  std::vector<int> used(fb.size(), 0);
  for (const cv::DMatch& m : matches) {
    const cv::Point2f d = fb.keypoints[m.trainIdx].pt - fa.keypoints[m.queryIdx].pt;
    // Levels above 0 see the shift in fractional level pixels: a corner may land on the
    // neighbouring level pixel.
    correct += cv::norm(d - cv::Point2f(7, -4)) <=
               1.5 * fa.pyramid.scales[fa.keypoints[m.queryIdx].octave];
    EXPECT_LE(m.distance, settings.max_distance);
    EXPECT_EQ(used[m.trainIdx]++, 0) << "mutual check leaves each train keypoint once";
  }
  std::printf("shifted copy: %zu matches of %zu keypoints, %d correct\n", matches.size(), fa.size(),
              correct);
  EXPECT_GT(matches.size(), 0.5 * fa.size());
  EXPECT_GT(correct, 0.98 * matches.size());
}

// A keyframe seeing a plain wall may keep a single descriptor: FLANN asserted when asked
// for more neighbours than it holds, which ended a run. Its one descriptor is matched.
TEST_P(ShiftedCopy, TrainSetOfOneDescriptor) {
  cv::Mat query(5, kDescriptorBytes, CV_8U);
  cv::RNG rng(3);
  rng.fill(query, cv::RNG::UNIFORM, 0, 256);
  const cv::Mat train = query.row(2).clone();
  MatcherSettings settings;
  settings.backend = GetParam();
  const std::vector<cv::DMatch> matches = match_descriptors(query, train, settings);
  ASSERT_EQ(matches.size(), 1u);
  EXPECT_EQ(matches[0].queryIdx, 2);
  EXPECT_EQ(matches[0].trainIdx, 0);
  EXPECT_EQ(match_descriptors(train, query, settings).size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(Backends, ShiftedCopy,
                         ::testing::Values(MatcherBackend::kFlannLsh, MatcherBackend::kBruteForce));

// The popcount path gives OpenCV's Hamming norm on every pair, including the extremes.
TEST(DescriptorDistance, EqualsOpenCvsHammingNorm) {
  cv::Mat descriptors(200, kDescriptorBytes, CV_8U);
  cv::RNG rng(11);
  rng.fill(descriptors, cv::RNG::UNIFORM, 0, 256);
  descriptors.row(1).setTo(0);
  descriptors.row(2).setTo(255);
  for (int i = 0; i < descriptors.rows; ++i)
    for (int j = 0; j < descriptors.rows; ++j)
      ASSERT_EQ(descriptor_distance(descriptors.ptr<uchar>(i), descriptors.ptr<uchar>(j)),
                cv::norm(descriptors.row(i), descriptors.row(j), cv::NORM_HAMMING))
          << i << " " << j;
  EXPECT_EQ(descriptor_distance(descriptors.ptr<uchar>(1), descriptors.ptr<uchar>(2)), 256);
  EXPECT_EQ(descriptor_distance(descriptors.ptr<uchar>(7), descriptors.ptr<uchar>(7)), 0);
}

TEST(DescriptorMatcher, FlannLshIsDeterministicAndLeavesTheCallersRng) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence sequence = TumSequence::open(folder);
  const FrameFeatures fa = extract_orb(sequence.load(0).rgb, sequence.camera(), OrbSettings{});
  const FrameFeatures fb = extract_orb(sequence.load(3).rgb, sequence.camera(), OrbSettings{});
  const MatcherSettings settings;  // FLANN LSH
  cv::theRNG() = cv::RNG(1234);
  const std::vector<cv::DMatch> first = match_descriptors(fa.descriptors, fb.descriptors, settings);
  EXPECT_EQ(cv::theRNG().state, cv::RNG(1234).state);
  cv::theRNG().next();  // a different generator state must not change the result
  const std::vector<cv::DMatch> second =
      match_descriptors(fa.descriptors, fb.descriptors, settings);
  EXPECT_TRUE(same_matches(first, second));
  ASSERT_GT(first.size(), 200u);

  // On other threads (each has its own cv::theRNG): same result.
  std::vector<std::vector<cv::DMatch>> parallel(4);
#pragma omp parallel for num_threads(2)
  for (int i = 0; i < 4; ++i)
    parallel[i] = match_descriptors(fa.descriptors, fb.descriptors, settings);
  for (const auto& p : parallel) EXPECT_TRUE(same_matches(first, p));
}

TEST(KeypointGrid, FindsExactlyThePointsWithinTheRadius) {
  cv::RNG rng(7);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 500; ++i)
    points.emplace_back(rng.uniform(-20.0, 660.0), rng.uniform(0.0, 480.0));
  const KeypointGrid grid(points, 10);
  for (const Eigen::Vector2d& centre : {Eigen::Vector2d(100, 100), Eigen::Vector2d(-30, 5),
                                        Eigen::Vector2d(640, 470), Eigen::Vector2d(2000, 2000)}) {
    for (double radius : {3.0, 17.0, 60.0}) {
      std::vector<int> expected;
      for (int i = 0; i < 500; ++i) {
        if ((points[i] - centre).norm() <= radius) expected.push_back(i);
      }
      std::vector<int> found = grid.within(centre, radius);
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected) << centre.transpose() << " r " << radius;
    }
  }
  EXPECT_TRUE(KeypointGrid({}, 10).within({0, 0}, 5).empty());
}

// Map points from frame A's keypoints and depth (groundtruth pose), matched into frame B with
// B's groundtruth pose: matches land on the projections, and each keypoint is used once.
TEST(ProjectionMatcher, MatchesLandOnTheGroundtruthProjections) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  const TumSequence sequence = TumSequence::open(folder);
  const Camera& camera = sequence.camera();
  const Trajectory& gt = *sequence.groundtruth();
  const RgbdFrame a = sequence.load(0), b = sequence.load(5);
  const Eigen::Isometry3d T_w_a = gt[*gt.nearest(a.stamp, 0.02)].T_w_c;
  const Eigen::Isometry3d T_w_b = gt[*gt.nearest(b.stamp, 0.02)].T_w_c;
  const FrameFeatures fa = extract_orb(a.rgb, camera, OrbSettings{});
  const FrameFeatures fb = extract_orb(b.rgb, camera, OrbSettings{});
  MapPointSet points;
  std::vector<cv::Mat> rows;
  const std::vector<float> depths = keypoint_depths(fa, a.depth);
  for (size_t i = 0; i < fa.size(); ++i) {
    if (!camera.is_valid_depth(depths[i])) continue;
    points.points_w.push_back(T_w_a * camera.back_project(fa.undistorted[i], depths[i]));
    rows.push_back(fa.descriptors.row(static_cast<int>(i)));
    points.octaves.push_back(fa.keypoints[i].octave);
  }
  cv::vconcat(rows, points.descriptors);
  const KeypointGrid grid(fb.undistorted);
  const std::vector<ProjectionMatch> matches =
      match_by_projection(points, T_w_b, camera, fb, grid, MatcherSettings{});
  int correct = 0;
  std::vector<int> used(fb.size(), 0);
  for (const ProjectionMatch& m : matches) {
    const Eigen::Vector2d uv = camera.project(T_w_b.inverse() * points.points_w[m.point]);
    correct += (fb.undistorted[m.keypoint] - uv).norm() < 5;
    EXPECT_EQ(used[m.keypoint]++, 0);
    EXPECT_LE(m.distance, MatcherSettings{}.projection_max_distance);
  }
  std::printf("projection: %zu map points, %zu matches, %d within 5 px\n", points.points_w.size(),
              matches.size(), correct);
  EXPECT_GT(matches.size(), 0.4 * points.points_w.size());
  EXPECT_GT(correct, 0.9 * matches.size());

  // A pose 30 cm off sideways moves projections out of the search windows: far fewer matches.
  Eigen::Isometry3d wrong = T_w_b;
  wrong.translation() += T_w_b.linear() * Eigen::Vector3d(0.3, 0, 0);
  EXPECT_LT(match_by_projection(points, wrong, camera, fb, grid, MatcherSettings{}).size(),
            matches.size() / 2);
}

}  // namespace
}  // namespace slamkit
