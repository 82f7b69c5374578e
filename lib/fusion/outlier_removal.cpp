#include "fusion/outlier_removal.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace slamkit {

std::vector<size_t> statistical_inliers(const std::vector<Eigen::Vector3f>& points, int mean_k,
                                        double std_ratio) {
  // The finite points, flat, as the k-d tree reads them. Non-finite ones stay out of the tree
  // and the statistics and are kept, as PCL does.
  std::vector<size_t> finite;
  std::vector<float> coordinates;
  for (size_t i = 0; i < points.size(); ++i)
    if (points[i].allFinite()) {
      finite.push_back(i);
      coordinates.insert(coordinates.end(), points[i].data(), points[i].data() + 3);
    }
  const int n = int(finite.size());
  // The query point comes back as its own first neighbour; a cloud smaller than mean_k + 1
  // gives each point the neighbours it has.
  const int neighbours = std::min(mean_k, n - 1);
  if (neighbours < 1) {  // no point has a neighbour to be measured against: all stay
    std::vector<size_t> all(points.size());
    std::iota(all.begin(), all.end(), size_t{0});
    return all;
  }
  const int searched = neighbours + 1;

  // PCL's k-d tree for unorganised clouds is this FLANN index (single tree, leaves of 15, exact,
  // unsorted results). Queried through PCL, each point opens an OpenMP region inside FLANN;
  // queried here in blocks of points, the searches take a quarter of the time.
  const flann::Matrix<float> dataset(coordinates.data(), size_t(n), 3);
  flann::Index<flann::L2_Simple<float>> index(dataset, flann::KDTreeSingleIndexParams(15));
  index.buildIndex();
  flann::SearchParams search(flann::FLANN_CHECKS_UNLIMITED, 0.0f, false);
  search.cores = 1;  // the blocks are spread over the threads below

  constexpr int kBlock = 4096;
  const int blocks = (n + kBlock - 1) / kBlock;
  std::vector<float> distances(static_cast<size_t>(n));
#pragma omp parallel
  {
    std::vector<int> indices(size_t(kBlock) * size_t(searched));
    std::vector<float> squared(indices.size());
#pragma omp for schedule(dynamic, 1)
    for (int b = 0; b < blocks; ++b) {
      const int first = b * kBlock, rows = std::min(kBlock, n - first);
      flann::Matrix<float> queries(coordinates.data() + 3 * size_t(first), size_t(rows), 3);
      flann::Matrix<int> found(indices.data(), size_t(rows), size_t(searched));
      flann::Matrix<float> found_squared(squared.data(), size_t(rows), size_t(searched));
      index.knnSearch(queries, found, found_squared, size_t(searched), search);
      for (int r = 0; r < rows; ++r) {
        double sum = 0.0;
        for (int k = 1; k < searched; ++k) sum += std::sqrt(found_squared[size_t(r)][size_t(k)]);
        distances[size_t(first + r)] = float(sum / neighbours);
      }
    }
  }
  // The statistics in PCL's order and precision (float distances summed in double).
  double sum = 0, squared_sum = 0;
  for (float d : distances) {
    sum += d;
    squared_sum += d * d;
  }
  const double mean = sum / double(n);
  const double variance = (squared_sum - sum * sum / double(n)) / (double(n) - 1);
  const double threshold = mean + std_ratio * std::sqrt(variance);

  std::vector<char> outlier(points.size(), 0);
  for (int i = 0; i < n; ++i) outlier[finite[size_t(i)]] = distances[size_t(i)] > threshold;
  std::vector<size_t> kept;
  for (size_t i = 0; i < points.size(); ++i)
    if (!outlier[i]) kept.push_back(i);
  return kept;
}

}  // namespace slamkit
