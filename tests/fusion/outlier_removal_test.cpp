#include "fusion/outlier_removal.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace slamkit {
namespace {

// Two dense clusters and a few far strays.
std::vector<Eigen::Vector3f> clusters_with_strays() {
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.02f);
  std::uniform_real_distribution<float> anywhere(-3.0f, 3.0f);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 1500; ++i) {
    const Eigen::Vector3f centre = i % 2 ? Eigen::Vector3f(1, 0, 2) : Eigen::Vector3f(-1, 0.5f, 2);
    points.push_back(centre + Eigen::Vector3f(noise(rng), noise(rng), noise(rng)));
    if (i % 100 == 0) points.push_back({anywhere(rng), anywhere(rng), anywhere(rng)});
  }
  return points;
}

// The filter's definition by brute force: float squared distances summed x, y, z (as the k-d
// tree's metric), the mean_k smallest after the point itself, PCL's statistics.
std::vector<size_t> brute_force_inliers(const std::vector<Eigen::Vector3f>& points, int mean_k,
                                        double std_ratio) {
  std::vector<float> mean_distance;
  for (const Eigen::Vector3f& p : points) {
    std::vector<float> squared;
    for (const Eigen::Vector3f& q : points) {
      float s = 0;
      for (int d = 0; d < 3; ++d) s += (p[d] - q[d]) * (p[d] - q[d]);
      squared.push_back(s);
    }
    std::partial_sort(squared.begin(), squared.begin() + mean_k + 1, squared.end());
    double sum = 0;
    for (int k = 1; k <= mean_k; ++k) sum += std::sqrt(squared[size_t(k)]);
    mean_distance.push_back(float(sum / mean_k));
  }
  double sum = 0, squared_sum = 0;
  for (float d : mean_distance) {
    sum += d;
    squared_sum += d * d;
  }
  const double n = double(points.size());
  const double threshold =
      sum / n + std_ratio * std::sqrt((squared_sum - sum * sum / n) / (n - 1));
  std::vector<size_t> kept;
  for (size_t i = 0; i < points.size(); ++i)
    if (mean_distance[i] <= threshold) kept.push_back(i);
  return kept;
}

TEST(StatisticalInliers, EqualsTheDefinitionComputedByBruteForce) {
  const std::vector<Eigen::Vector3f> points = clusters_with_strays();
  const std::vector<size_t> kept = statistical_inliers(points, 20, 2.0);
  EXPECT_EQ(kept, brute_force_inliers(points, 20, 2.0));
  // Every stray (one per 100 cluster points, metres away) is gone, the clusters stay.
  EXPECT_EQ(points.size() - kept.size() >= 15, true) << points.size() - kept.size();
  EXPECT_GT(kept.size(), 1450u);
}

TEST(StatisticalInliers, SameAtOneAndTwoThreads) {
  const std::vector<Eigen::Vector3f> points = clusters_with_strays();
  omp_set_num_threads(1);
  const std::vector<size_t> one = statistical_inliers(points, 8, 1.0);
  omp_set_num_threads(2);
  EXPECT_EQ(statistical_inliers(points, 8, 1.0), one);
}

// A cloud smaller than mean_k + 1 gives each point the neighbours it has.
TEST(StatisticalInliers, FewerPointsThanNeighboursUsesThoseThereAre) {
  const std::vector<Eigen::Vector3f> points = {
      {0, 0, 1}, {0.01f, 0, 1}, {0, 0.01f, 1}, {0.01f, 0.01f, 1}, {0.005f, 0.005f, 1}, {2, 2, 3}};
  EXPECT_EQ(statistical_inliers(points, 20, 1.0), brute_force_inliers(points, 5, 1.0));
  EXPECT_EQ(statistical_inliers(points, 20, 1.0), (std::vector<size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(statistical_inliers({{1, 2, 3}}, 20, 1.0), std::vector<size_t>{0});
}

// Non-finite points stay out of the statistics and are kept, as PCL keeps them.
TEST(StatisticalInliers, NonFinitePointsAreKeptAndLeftOutOfTheStatistics) {
  std::vector<Eigen::Vector3f> points = clusters_with_strays();
  const std::vector<size_t> finite_kept = statistical_inliers(points, 20, 2.0);
  points.insert(points.begin(), Eigen::Vector3f(NAN, 0, 1));
  std::vector<size_t> expected = {0};
  for (size_t i : finite_kept) expected.push_back(i + 1);
  EXPECT_EQ(statistical_inliers(points, 20, 2.0), expected);
}

}  // namespace
}  // namespace slamkit
