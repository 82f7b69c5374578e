#include "datasets/synth/hand_shake.h"

#include <cmath>

#include "datasets/synth/counter_rng.h"

namespace slamkit::synth {

HandShake::HandShake(uint64_t seed, double translation_rms_m, double rotation_rms_rad,
                     double period_s) {
  constexpr int kWaves = 3;
  CounterRng rng(seed, kStreamShake, 0);
  for (int axis = 0; axis < 6; ++axis) {
    const double rms = axis < 3 ? translation_rms_m : rotation_rms_rad;
    for (int k = 0; k < kWaves; ++k) {
      double frequency = rng.uniform(0.3, 2.0);
      if (period_s > 0) frequency = std::max(1.0, std::round(frequency * period_s)) / period_s;
      // kWaves sinusoids of amplitude a have an RMS of a * sqrt(kWaves / 2).
      axes_[axis].push_back({frequency, rng.uniform(0, 2 * M_PI), rms * std::sqrt(2.0 / kWaves)});
    }
  }
}

Eigen::Isometry3d HandShake::offset(double t) const {
  Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
  for (int axis = 0; axis < 6; ++axis)
    for (const Wave& w : axes_[axis])
      x[axis] += w.amplitude * std::sin(2 * M_PI * w.frequency_hz * t + w.phase);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = x.head<3>();
  const Eigen::Vector3d rotation = x.tail<3>();
  if (rotation.norm() > 0)
    T.linear() = Eigen::AngleAxisd(rotation.norm(), rotation.normalized()).toRotationMatrix();
  return T;
}

}  // namespace slamkit::synth
