#pragma once
// The axial depth noise of a Kinect v1 (structured light), Nguyen, Izadi and Lovell 2012, eq. 6:
// sigma_z = 0.0012 + 0.0019 (z - 0.4)^2 + 0.0001 / sqrt(z) * theta^2 / (pi/2 - theta)^2 metres,
// at depth z (metres) and incidence angle theta (radians). It includes the disparity
// quantisation's share. The synthetic kinect sensor draws its noise from it, and map fusion
// weighs each depth measurement by it (docs/sensor.md, docs/method.md#map-fusion).
#include <algorithm>
#include <cmath>

namespace slamkit {

inline double kinect_axial_sigma(double z, double theta) {
  // The angular term grows without bound towards grazing; theta is capped where the sensor
  // stops returning depth anyway.
  const double t = std::min(theta, 80.0 * M_PI / 180.0);
  return 0.0012 + 0.0019 * (z - 0.4) * (z - 0.4) +
         0.0001 / std::sqrt(z) * t * t / ((M_PI / 2 - t) * (M_PI / 2 - t));
}

}  // namespace slamkit
