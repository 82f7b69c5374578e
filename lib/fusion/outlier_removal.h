#pragma once
// Statistical outlier removal as PCL's StatisticalOutlierRemoval computes it, with its
// k-nearest-neighbour searches (nearly all of its time) spread over OpenMP threads: PCL 1.13's
// runs on one thread, 1.9 s of the 4.2 s fusion of synthetic desk 600. Same searcher (PCL's
// k-d tree), same per-point mean distance, same threshold, so the kept points are PCL's, at any
// thread count.
#include <Eigen/Core>
#include <vector>

namespace slamkit {

// Indices (ascending) of the points whose mean distance to their mean_k nearest neighbours is at
// most mean + std_ratio x standard deviation of that distance over all points. Non-finite
// points are kept out of the statistics and kept in the output, as PCL does.
std::vector<size_t> statistical_inliers(const std::vector<Eigen::Vector3f>& points, int mean_k,
                                        double std_ratio);

}  // namespace slamkit
