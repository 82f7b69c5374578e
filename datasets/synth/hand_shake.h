#pragma once
// Small smooth pose perturbations, like a hand holding the camera: on each of the six axes a
// sum of sinusoids with seeded frequencies (0.3..2 Hz) and phases.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

namespace slamkit::synth {

class HandShake {
 public:
  // period_s > 0 rounds every frequency to whole cycles over the period, so that the shake at
  // t and t + period is the same (closed loops).
  HandShake(uint64_t seed, double translation_rms_m, double rotation_rms_rad, double period_s = 0);

  // The perturbation at time t (seconds), in the camera frame: T_w_c * offset(t).
  Eigen::Isometry3d offset(double t) const;

 private:
  struct Wave {
    double frequency_hz, phase, amplitude;
  };
  std::array<std::vector<Wave>, 6> axes_;  // tx ty tz, then a rotation vector
};

}  // namespace slamkit::synth
