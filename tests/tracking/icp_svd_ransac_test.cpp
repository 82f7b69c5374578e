#include "tracking/icp_svd_ransac.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/pose.h"

namespace slamkit {
namespace {

constexpr double kDeg = M_PI / 180;

Eigen::Isometry3d known_motion() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(5 * kDeg, Eigen::Vector3d(0.3, -1, 0.2).normalized()).matrix();
  T.translation() = Eigen::Vector3d(0.10, -0.05, 0.08);
  return T;
}

struct Pairs {
  std::vector<Eigen::Vector3d> prev, curr;
  std::vector<bool> is_outlier;
};

// Points 0.5-4 m in front of the previous camera; q' = T^-1 q + noise. An outlier's q' is
// moved 0.3-1 m from where it belongs, beyond any inlier threshold.
Pairs make_pairs(int n, double outlier_ratio, double noise, const Eigen::Isometry3d& T_prev_curr,
                 uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> xy(-1.5, 1.5), z(0.5, 4.0), u(0, 1), off(0.3, 1.0);
  std::normal_distribution<double> gauss(0, noise);
  Pairs p;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d q(xy(rng), xy(rng), z(rng));
    Eigen::Vector3d q_curr = T_prev_curr.inverse() * q;
    q_curr += Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    const bool outlier = u(rng) < outlier_ratio;
    if (outlier) q_curr += off(rng) * Eigen::Vector3d(xy(rng), xy(rng), xy(rng)).normalized();
    p.prev.push_back(q);
    p.curr.push_back(q_curr);
    p.is_outlier.push_back(outlier);
  }
  return p;
}

double translation_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}
double rotation_error_deg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return rotation_angle(a.inverse() * b) / kDeg;
}

TEST(FitRigid, ExactOnNoiseFreePairs) {
  const Eigen::Isometry3d T = known_motion();
  const Pairs p = make_pairs(20, 0, 0, T, 1);
  std::vector<int> all(20);
  for (int i = 0; i < 20; ++i) all[i] = i;
  const auto fit = fit_rigid(p.prev, p.curr, all);
  ASSERT_TRUE(fit);
  EXPECT_LT(translation_error(*fit, T), 1e-12);
  EXPECT_LT(rotation_error_deg(*fit, T), 1e-9);
  EXPECT_GT(fit->linear().determinant(), 0);  // a rotation, never a reflection
}

TEST(FitRigid, RejectsCollinearPoints) {
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 10; ++i) line.emplace_back(0.1 * i, 0.2 * i, 1 + 0.05 * i);
  std::vector<int> all(10);
  for (int i = 0; i < 10; ++i) all[i] = i;
  EXPECT_FALSE(fit_rigid(line, line, all));
}

TEST(IcpSvdRansac, RecoversMotionAndOutliers) {
  const Eigen::Isometry3d T = known_motion();
  const Pairs p = make_pairs(500, 0.35, 0.001, T, 2);
  const RigidFit fit = icp_svd_ransac(p.prev, p.curr, RansacSettings{});
  ASSERT_TRUE(fit.ok());
  EXPECT_LT(translation_error(fit.T_prev_curr, T), 1e-3);
  EXPECT_LT(rotation_error_deg(fit.T_prev_curr, T), 0.05);
  ASSERT_EQ(fit.inliers.size(), p.prev.size());
  int inliers = 0;
  for (size_t i = 0; i < p.prev.size(); ++i) {
    EXPECT_EQ(fit.inliers[i], !p.is_outlier[i]) << "pair " << i;
    inliers += !p.is_outlier[i];
  }
  EXPECT_EQ(fit.num_inliers, inliers);
  EXPECT_LT(fit.inlier_rmse, 0.003);  // sqrt(3 * 2) mm of noise per pair at most
  EXPECT_LT(fit.iterations, RansacSettings{}.max_iterations);  // the adaptive rule stopped it
}

TEST(IcpSvdRansac, SameSeedSameResult) {
  const Pairs p = make_pairs(300, 0.4, 0.002, known_motion(), 3);
  const RigidFit a = icp_svd_ransac(p.prev, p.curr, RansacSettings{});
  const RigidFit b = icp_svd_ransac(p.prev, p.curr, RansacSettings{});
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a.T_prev_curr.matrix(), b.T_prev_curr.matrix());  // bit for bit
  EXPECT_EQ(a.inliers, b.inliers);
  EXPECT_EQ(a.iterations, b.iterations);
  RansacSettings other;
  other.seed = 7;
  const RigidFit c = icp_svd_ransac(p.prev, p.curr, other);
  ASSERT_TRUE(c.ok());
  EXPECT_LT(translation_error(a.T_prev_curr, c.T_prev_curr), 1e-3);
}

TEST(IcpSvdRansac, TooFewPairsIsAStatusNotACrash) {
  const Pairs p = make_pairs(2, 0, 0, known_motion(), 4);
  EXPECT_EQ(icp_svd_ransac(p.prev, p.curr, RansacSettings{}).status, RigidFitStatus::kTooFewPairs);
  EXPECT_EQ(icp_svd_ransac({}, {}, RansacSettings{}).status, RigidFitStatus::kTooFewPairs);
  const Pairs q = make_pairs(10, 0, 0, known_motion(), 5);
  std::vector<Eigen::Vector3d> shorter(q.curr.begin(), q.curr.end() - 1);
  EXPECT_EQ(icp_svd_ransac(q.prev, shorter, RansacSettings{}).status, RigidFitStatus::kTooFewPairs);
}

TEST(IcpSvdRansac, CollinearPointsAreDegenerate) {
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 60; ++i) line.emplace_back(0.05 * i, 0.02 * i, 1 + 0.03 * i);
  const RigidFit fit = icp_svd_ransac(line, line, RansacSettings{});
  EXPECT_EQ(fit.status, RigidFitStatus::kDegenerate);
  EXPECT_FALSE(fit.ok());
}

TEST(IcpSvdRansac, ThresholdGrowsWithDepthSquared) {
  const RansacSettings s;
  EXPECT_DOUBLE_EQ(ransac_threshold(s, 0), s.threshold_base);
  EXPECT_NEAR(ransac_threshold(s, 3) - s.threshold_base,
              9 * (ransac_threshold(s, 1) - s.threshold_base), 1e-15);
}

}  // namespace
}  // namespace slamkit
