#include "fusion/outlier_removal.h"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <cmath>
#include <vector>

namespace slamkit {

std::vector<size_t> statistical_inliers(const std::vector<Eigen::Vector3f>& points, int mean_k,
                                        double std_ratio) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(points.size());
  for (const Eigen::Vector3f& p : points) cloud->push_back({p.x(), p.y(), p.z()});
  // PCL's searcher for an unorganised cloud, unsorted results as it asks; queries only read it.
  pcl::search::KdTree<pcl::PointXYZ> searcher(false);
  searcher.setInputCloud(cloud);
  const int n = int(cloud->size());
  const int searched = mean_k + 1;  // the query point comes back as its own first neighbour
  std::vector<float> distances(size_t(n), 0.0f);
  std::vector<char> valid(size_t(n), 0);
#pragma omp parallel
  {
    pcl::Indices neighbours(static_cast<size_t>(searched));
    std::vector<float> squared(static_cast<size_t>(searched));
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const pcl::PointXYZ& p = (*cloud)[size_t(i)];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      if (searcher.nearestKSearch(i, searched, neighbours, squared) == 0) continue;
      double sum = 0.0;
      for (int k = 1; k < searched; ++k) sum += std::sqrt(squared[size_t(k)]);
      distances[size_t(i)] = float(sum / mean_k);
      valid[size_t(i)] = 1;
    }
  }
  // The statistics in PCL's order and precision (float distances summed in double).
  double sum = 0, squared_sum = 0;
  int count = 0;
  for (int i = 0; i < n; ++i) {
    sum += distances[size_t(i)];
    squared_sum += distances[size_t(i)] * distances[size_t(i)];
    count += valid[size_t(i)];
  }
  const double mean = sum / double(count);
  const double variance = (squared_sum - sum * sum / double(count)) / (double(count) - 1);
  const double threshold = mean + std_ratio * std::sqrt(variance);

  std::vector<size_t> kept;
  for (int i = 0; i < n; ++i)
    if (distances[size_t(i)] <= threshold) kept.push_back(size_t(i));
  return kept;
}

}  // namespace slamkit
