#include "eval/metrics/statistics.h"

#include <algorithm>
#include <cmath>

namespace slamkit::eval {

ErrorStats compute_stats(const std::vector<double>& values) {
  ErrorStats s;
  s.count = values.size();
  if (values.empty()) return s;
  const double n = double(values.size());
  double sum = 0, sum_sq = 0;
  for (double v : values) {
    sum += v;
    sum_sq += v * v;
  }
  s.mean = sum / n;
  s.rmse = std::sqrt(sum_sq / n);
  double var = 0;  // two-pass, like numpy, rather than sum_sq/n - mean^2 (cancellation)
  for (double v : values) var += (v - s.mean) * (v - s.mean);
  s.std = std::sqrt(var / n);

  // The middle order statistics by selection (as numpy's median partitions), not a full sort.
  std::vector<double> part = values;
  const size_t mid = part.size() / 2;
  std::nth_element(part.begin(), part.begin() + long(mid), part.end());
  s.median = part.size() % 2
                 ? part[mid]
                 : 0.5 * (*std::max_element(part.begin(), part.begin() + long(mid)) + part[mid]);
  const auto [min, max] = std::minmax_element(values.begin(), values.end());
  s.min = *min;
  s.max = *max;
  return s;
}

}  // namespace slamkit::eval
