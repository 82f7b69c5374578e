#include "datasets/synth/sensor_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slamkit::synth {
namespace {

TEST(SensorModel, DepthNoiseFollowsTheKinectModelAndIsQuantised) {
  const SensorModel sensor;
  for (double z : {0.8, 2.0, 4.5}) {
    double sum = 0, sum2 = 0;
    int valid = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      CounterRng rng(1, kStreamPixel, i);
      const uint16_t raw = sensor.measure_depth(z, false, 5000.0, rng);
      if (raw == 0) continue;
      const double error = raw / 5000.0 - z;
      sum += error, sum2 += error * error, ++valid;
    }
    const double sigma = SensorModel::depth_sigma(z), mean = sum / valid;
    EXPECT_NEAR(mean, 0, 4 * sigma / std::sqrt(valid)) << z;
    // Quantisation (1/5000 m) adds 1/12 unit^2 of variance.
    const double expected = std::sqrt(sigma * sigma + std::pow(1 / 5000.0, 2) / 12);
    EXPECT_NEAR(std::sqrt(sum2 / valid - mean * mean), expected, 0.03 * expected) << z;
    // A few random dropouts, not many.
    EXPECT_GT(valid, n * 0.99);
    EXPECT_LT(valid, n);
  }
  EXPECT_NEAR(SensorModel::depth_sigma(0.4), 0.0012, 1e-15);
  EXPECT_NEAR(SensorModel::depth_sigma(3.4), 0.0012 + 0.0019 * 9, 1e-15);
}

TEST(SensorModel, NoDepthAtGrazingAnglesOrOutOfRange) {
  const SensorModel sensor;
  CounterRng rng(1, kStreamPixel, 0);
  EXPECT_EQ(sensor.measure_depth(2.0, true, 5000.0, rng), 0);
  EXPECT_EQ(sensor.measure_depth(6.5, false, 5000.0, rng), 0);
  EXPECT_EQ(sensor.measure_depth(0.3, false, 5000.0, rng), 0);
  EXPECT_NEAR(sensor.min_cos_incidence(), std::cos(78.0 * M_PI / 180), 1e-15);
}

TEST(CounterRng, ApproximateGaussianHasUnitVariance) {
  double sum = 0, sum2 = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    CounterRng rng(3, 0, i);
    const double x = rng.approx_gaussian();
    sum += x, sum2 += x * x;
  }
  EXPECT_NEAR(sum / n, 0, 0.02);
  EXPECT_NEAR(sum2 / n, 1, 0.02);
}

}  // namespace
}  // namespace slamkit::synth
