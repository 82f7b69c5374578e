#pragma once
// What the simulated Kinect-like sensor does to the ideal image: colour noise, and depth
// noise, quantisation and missing data. Written by hand: it is the model under test.
#include <cstdint>

#include "datasets/synth/counter_rng.h"

namespace slamkit::synth {

struct SensorModel {
  double colour_sigma = 2.0;           // grey levels, independent per channel
  double min_range_m = 0.4;            // a Kinect v1 measures nothing closer
  double max_range_m = 6.0;            // nor farther
  double max_incidence_deg = 78.0;     // grazing surfaces return no depth
  double dropout_probability = 0.002;  // isolated missing pixels
  int holes_per_frame = 4;             // small discs of missing depth, 2..6 px radius

  // Axial noise (metres) at depth z, Nguyen, Izadi and Lovell 2012. Drawn nearly normal
  // (CounterRng::approx_gaussian8: no tails beyond 4.9 sigma, and no transcendental calls).
  static double depth_sigma(double z) { return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4); }

  // Surfaces seen at a cosine of incidence below this return no depth.
  double min_cos_incidence() const;

  // The raw 16-bit depth for a surface at camera z (metres), in units of 1/depth_scale
  // metres; 0 when the sensor returns nothing. `grazing`: seen beyond max_incidence_deg.
  uint16_t measure_depth(double z, bool grazing, double depth_scale, CounterRng& rng) const;
};

}  // namespace slamkit::synth
