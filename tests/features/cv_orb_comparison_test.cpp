// Our ORB against cv::ORB with the same budget (1000 features, 4 levels, factor 1.2) on real
// TUM frames, judged with groundtruth poses and depth: repeatability of the keypoints and the
// fraction of descriptor matches that land where the geometry says.
//
// Repeatability as defined here (some keypoint of B within 3 px) also counts chance hits, and
// they depend on the layout: cv::ORB clusters its corners on texture, so a point projected a
// dozen pixels off still finds a neighbour 17-27% of the time; our spread keypoints 9-15%.
// Spreading therefore loses on the raw number while gaining coverage. So: the paper's mode
// (best M by response, no spreading) must beat cv::ORB on the raw number, and the default on
// repeatability above chance (raw minus the rate measured with deliberately offset
// projections). Both must match at least as correctly.
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/features2d.hpp>
#include <optional>
#include <string>
#include <vector>

#include "features/descriptor_matcher.h"
#include "features/equivalent_grey.h"
#include "features/frame_features.h"
#include "features/orb_extractor.h"
#include "io/tum_sequence.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

// Keypoints, their undistorted positions and descriptors: what both extractors give.
struct Features {
  std::vector<cv::KeyPoint> keypoints;
  std::vector<Eigen::Vector2d> undistorted;
  cv::Mat descriptors;
};

Features ours(const RgbdFrame& frame, const Camera& camera, const OrbSettings& settings) {
  FrameFeatures f = extract_orb(frame.rgb, camera, settings);
  return {f.keypoints, f.undistorted, f.descriptors};
}

Features opencv_orb(const RgbdFrame& frame, const Camera& camera) {
  Features f;
  // On the image ours detects on, so that the two methods are compared, not two greys.
  cv::ORB::create(1000, 1.2f, 4)
      ->detectAndCompute(equivalent_grey(frame.rgb), cv::noArray(), f.keypoints, f.descriptors);
  std::vector<Eigen::Vector2d> raw;
  for (const cv::KeyPoint& k : f.keypoints) raw.emplace_back(k.pt.x, k.pt.y);
  f.undistorted = camera.undistort_pixels(raw);
  return f;
}

struct Score {
  int considered = 0, repeated = 0;  // keypoints of A with depth, projecting inside B
  double repeated_by_chance = 0;     // the same with projections moved off by ~15 px
  int matches = 0, correct = 0;      // matches whose A keypoint has depth, projecting inside B
  void add(const Score& o) {
    considered += o.considered, repeated += o.repeated, matches += o.matches, correct += o.correct;
    repeated_by_chance += o.repeated_by_chance;
  }
  double repeatability() const { return considered ? double(repeated) / considered : 0; }
  double chance() const { return considered ? repeated_by_chance / considered : 0; }
  double above_chance() const { return repeatability() - chance(); }
  double correct_fraction() const { return matches ? double(correct) / matches : 0; }
};

// Whether a keypoint of B of similar scale (octave within 1) lies within 3 px of uv.
bool has_keypoint_near(const Features& b, const Eigen::Vector2d& uv, int octave) {
  for (size_t j = 0; j < b.keypoints.size(); ++j) {
    if (std::abs(b.keypoints[j].octave - octave) <= 1 && (b.undistorted[j] - uv).norm() <= 3.0) {
      return true;
    }
  }
  return false;
}

// Where each keypoint of A lands in B by groundtruth (nullopt: no depth, or outside B's
// image by less than 31 px, the border cv::ORB leaves out).
std::vector<std::optional<Eigen::Vector2d>> project_into_b(const Features& a,
                                                           const cv::Mat& depth_a,
                                                           const Camera& camera,
                                                           const Eigen::Isometry3d& T_b_a) {
  std::vector<std::optional<Eigen::Vector2d>> landed(a.keypoints.size());
  constexpr double kMargin = 31;
  for (size_t i = 0; i < a.keypoints.size(); ++i) {
    const float z = depth_at(depth_a, a.keypoints[i]);
    if (!camera.is_valid_depth(z)) continue;
    const Eigen::Vector3d p_b = T_b_a * camera.back_project(a.undistorted[i], z);
    if (p_b.z() <= 0) continue;
    const Eigen::Vector2d uv = camera.project(p_b);
    if (uv.x() < kMargin || uv.y() < kMargin || uv.x() > camera.width - 1 - kMargin ||
        uv.y() > camera.height - 1 - kMargin) {
      continue;
    }
    landed[i] = uv;
  }
  return landed;
}

Score score_pair(const Features& a, const Features& b, const cv::Mat& depth_a, const Camera& camera,
                 const Eigen::Isometry3d& T_b_a) {
  const auto landed = project_into_b(a, depth_a, camera, T_b_a);
  Score s;
  for (size_t i = 0; i < landed.size(); ++i) {
    if (!landed[i]) continue;
    ++s.considered;
    const int octave = a.keypoints[i].octave;
    s.repeated += has_keypoint_near(b, *landed[i], octave);
    const Eigen::Vector2d offsets[] = {{12, 9}, {-10, 14}, {15, -8}, {-13, -11}};
    for (const Eigen::Vector2d& offset : offsets) {
      s.repeated_by_chance += has_keypoint_near(b, *landed[i] + offset, octave) / 4.0;
    }
  }
  MatcherSettings matching;
  matching.backend = MatcherBackend::kBruteForce;  // exact, so only the features differ
  for (const cv::DMatch& m : match_descriptors(a.descriptors, b.descriptors, matching)) {
    if (!landed[m.queryIdx]) continue;
    ++s.matches;
    if ((b.undistorted[m.trainIdx] - *landed[m.queryIdx]).norm() <= 5.0) ++s.correct;
  }
  return s;
}

void print(const char* name, const Score& s) {
  std::printf("  %-22s repeatability %.3f (chance %.3f, above %.3f)  correct matches %.3f of %d\n",
              name, s.repeatability(), s.chance(), s.above_chance(), s.correct_fraction(),
              s.matches);
}

// Scores of ours (default and paper mode) and cv::ORB over frame pairs of a sequence.
void compare_on(const std::filesystem::path& folder,
                const std::vector<std::pair<int, int>>& pairs) {
  const TumSequence sequence = TumSequence::open(folder);
  ASSERT_TRUE(sequence.groundtruth().has_value());
  const Trajectory& gt = *sequence.groundtruth();
  const Camera& camera = sequence.camera();
  OrbSettings paper;
  paper.spread_over_image = false;
  Score ours_default, ours_paper, opencv;
  for (const auto& [ia, ib] : pairs) {
    const RgbdFrame a = sequence.load(ia), b = sequence.load(ib);
    const auto ga = gt.nearest(a.stamp, 0.02), gb = gt.nearest(b.stamp, 0.02);
    ASSERT_TRUE(ga && gb) << "no groundtruth for frames " << ia << ", " << ib;
    const Eigen::Isometry3d T_b_a = gt[*gb].T_w_c.inverse() * gt[*ga].T_w_c;
    ours_default.add(score_pair(ours(a, camera, {}), ours(b, camera, {}), a.depth, camera, T_b_a));
    ours_paper.add(
        score_pair(ours(a, camera, paper), ours(b, camera, paper), a.depth, camera, T_b_a));
    opencv.add(score_pair(opencv_orb(a, camera), opencv_orb(b, camera), a.depth, camera, T_b_a));
  }
  std::printf("%s, %zu frame pairs:\n", folder.filename().c_str(), pairs.size());
  print("ours (default)", ours_default);
  print("ours (paper: no spread)", ours_paper);
  print("cv::ORB(1000, 1.2, 4)", opencv);

  constexpr double kTolerance = 0.01;
  EXPECT_GE(ours_paper.repeatability(), opencv.repeatability() - kTolerance);
  // Measured: fr2 0.653 against 0.664 (the one place cv::ORB leads), fr1 0.571 against 0.514.
  constexpr double kSpreadTolerance = 0.015;
  EXPECT_GE(ours_default.above_chance(), opencv.above_chance() - kSpreadTolerance);
  EXPECT_GE(ours_default.correct_fraction(), opencv.correct_fraction() - kTolerance);
  EXPECT_GE(ours_paper.correct_fraction(), opencv.correct_fraction() - kTolerance);
}

TEST(CvOrbComparison, Freiburg2DeskAtLeastAsGoodAsOpenCv) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg2_desk_first50");
  std::vector<std::pair<int, int>> pairs;
  for (int k = 0; k + 5 < 50; k += 10) pairs.insert(pairs.end(), {{k, k + 1}, {k, k + 5}});
  compare_on(folder, pairs);
}

TEST(CvOrbComparison, Freiburg1DeskAtLeastAsGoodAsOpenCv) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg1_desk_9frames");
  compare_on(folder, {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 3}, {3, 6}, {2, 7}});
}

}  // namespace
}  // namespace slamkit
