#pragma once
// Counter-based random numbers: every value is a pure function of (seed, stream, index), so
// images come out identical whatever the thread count or the order pixels are rendered in
// (a shared generator would make them depend on scheduling).
#include <cstdint>

namespace slamkit::synth {

// SplitMix64's finaliser: a cheap bijective 64-bit mix with good avalanche.
inline uint64_t mix64(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

class CounterRng {
 public:
  CounterRng(uint64_t seed, uint64_t stream, uint64_t index)
      : state_(mix64(mix64(mix64(seed) ^ stream) ^ index)) {}

  uint64_t next() {
    state_ += 0x9E3779B97F4A7C15ull;
    return mix64(state_);
  }
  // Uniform in [0, 1).
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Zero mean, unit variance, nearly normal: the sum of four 16-bit uniforms (Irwin-Hall),
  // bounded at +-3.5; no transcendental calls, which would cost more than the ray cast.
  double approx_gaussian() { return (sum_of_four_uniforms() - 2.0) * 1.7320508075688772; }
  // The same from eight uniforms: closer to normal, bounded at +-4.9.
  double approx_gaussian8() {
    return (sum_of_four_uniforms() + sum_of_four_uniforms() - 4.0) * 1.2247448713915890;
  }

 private:
  double sum_of_four_uniforms() {
    const uint64_t r = next();
    const uint64_t sum = (r & 0xFFFF) + ((r >> 16) & 0xFFFF) + ((r >> 32) & 0xFFFF) + (r >> 48);
    return double(sum) / 65536.0;
  }

  uint64_t state_;
};

// Streams keep the random choices of different purposes independent for the same seed.
enum RngStream : uint64_t {
  kStreamTexture = 1,
  kStreamShake = 2,
  kStreamPixel = 3,
  kStreamDepthHoles = 4,
  // The kinect sensor's (kinect_sensor.h):
  kStreamDepthStamps = 5,
  kStreamExposure = 6,
  kStreamColourNoise = 7,
  kStreamDepthNoise = 8,
  kStreamDepthEdges = 9,
  kStreamDepthLateral = 10,
};

}  // namespace slamkit::synth
