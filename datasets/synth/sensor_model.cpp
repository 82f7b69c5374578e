#include "datasets/synth/sensor_model.h"

#include <cmath>

namespace slamkit::synth {

double SensorModel::min_cos_incidence() const { return std::cos(max_incidence_deg * M_PI / 180.0); }

uint16_t SensorModel::measure_depth(double z, bool grazing, double depth_scale,
                                    CounterRng& rng) const {
  if (grazing || z < min_range_m || z > max_range_m) return 0;
  if (rng.uniform() < dropout_probability) return 0;
  const long raw = std::lround((z + depth_sigma(z) * rng.approx_gaussian8()) * depth_scale);
  return raw < 1 || raw > 65535 ? 0 : uint16_t(raw);
}

}  // namespace slamkit::synth
