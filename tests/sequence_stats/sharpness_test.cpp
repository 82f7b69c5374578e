// Sharpness falls as blur grows; angular speed from a trajectory of known rotation rate; the
// order statistics and correlation the summaries use.
#include "eval/sequence_stats/sharpness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "eval/sequence_stats/angular_speed.h"
#include "eval/sequence_stats/distribution.h"

namespace slamkit::stats {
namespace {

TEST(Sharpness, FallsStrictlyAsTheBlurKernelGrows) {
  cv::Mat texture(480, 640, CV_8UC3);
  cv::RNG(3).fill(texture, cv::RNG::UNIFORM, 0, 256);
  double previous = laplacian_variance(texture);
  for (const int k : {3, 5, 9, 15, 25}) {
    cv::Mat blurred;
    cv::GaussianBlur(texture, blurred, {k, k}, 0);
    const double s = laplacian_variance(blurred);
    EXPECT_LT(s, previous) << "kernel " << k;
    previous = s;
  }
  // Motion blur too: a horizontal box kernel of growing length.
  previous = laplacian_variance(texture);
  for (const int k : {3, 7, 15}) {
    cv::Mat blurred;
    cv::blur(texture, blurred, {k, 1});
    const double s = laplacian_variance(blurred);
    EXPECT_LT(s, previous) << "length " << k;
    previous = s;
  }
  EXPECT_EQ(laplacian_variance(cv::Mat(480, 640, CV_8UC1, cv::Scalar(90))), 0.0);
}

TEST(AngularSpeed, RecoversAConstantRotationRate) {
  // 100 Hz poses turning at 30 deg/s about a tilted axis, with 3 s of it.
  Trajectory gt;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  for (int k = 0; k <= 300; ++k) {
    const double t = 100.0 + 0.01 * k;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::AngleAxisd(30.0 * M_PI / 180.0 * (t - 100.0), axis).toRotationMatrix();
    T.translation() = Eigen::Vector3d(t, 0, 0);
    gt.push_back(t, T);
  }
  const auto speed = angular_speed_deg(gt, 101.5);
  ASSERT_TRUE(speed);
  EXPECT_NEAR(*speed, 30.0, 1e-6);
  EXPECT_FALSE(angular_speed_deg(gt, 105.0));  // after the groundtruth ends
  EXPECT_FALSE(angular_speed_deg(gt, 99.0));   // before it starts
}

TEST(Distribution, QuantilesAsNumpyAndPearson) {
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.25), 1.75);  // numpy.quantile([1,2,3,4], .25)
  EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(quantile({}, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(quantile({5}, 0.75), 5.0);
  EXPECT_NEAR(*pearson({1, 2, 3, 4}, {10, 8, 6, 4}), -1.0, 1e-12);
  EXPECT_NEAR(*pearson({1, 2, 3, 4}, {1, 3, 2, 4}), 0.8, 1e-12);
  EXPECT_FALSE(pearson({1, 2}, {3, 4}));
  EXPECT_FALSE(pearson({1, 2, 3}, {5, 5, 5}));
}

}  // namespace
}  // namespace slamkit::stats
