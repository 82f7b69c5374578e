#pragma once
// The camera's angular speed at a moment, from a groundtruth trajectory.
#include <optional>

#include "core/trajectory.h"

namespace slamkit::stats {

// Degrees per second between the poses nearest to stamp - half_window and stamp + half_window
// (each within half_window of its target), over their actual time apart; nullopt when either
// is missing or both are the same pose. The default spans about one frame each side at 30 Hz.
std::optional<double> angular_speed_deg(const Trajectory& groundtruth, double stamp,
                                        double half_window = 1.0 / 30.0);

}  // namespace slamkit::stats
