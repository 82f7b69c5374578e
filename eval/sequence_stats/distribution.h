#pragma once
// Order statistics and correlation of a sample, which neither OpenCV nor Eigen offers for a
// plain vector; written here by hand.
#include <optional>
#include <vector>

namespace slamkit::stats {

// The q-quantile (0..1) with numpy's default linear interpolation; 0 for an empty sample.
double quantile(std::vector<double> values, double q);
inline double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

// Pearson's correlation of paired samples; nullopt for fewer than 3 pairs or a constant side.
std::optional<double> pearson(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace slamkit::stats
