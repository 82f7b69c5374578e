#pragma once
// Summary statistics of an error vector, computed as the benchmark scripts do with numpy.
#include <cstddef>
#include <vector>

namespace slamkit::eval {

struct ErrorStats {
  size_t count = 0;
  double rmse = 0;
  double mean = 0;
  double median = 0;  // numpy: mean of the two middle values for an even count
  double std = 0;     // population standard deviation (numpy.std, ddof=0)
  double min = 0;
  double max = 0;
};

// All zero for an empty vector.
ErrorStats compute_stats(const std::vector<double>& values);

}  // namespace slamkit::eval
