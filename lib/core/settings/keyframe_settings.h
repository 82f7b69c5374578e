#pragma once
// Keyframe selection settings (docs/method.md#keyframes).
#include <cstdint>

namespace slamkit {

struct KeyframeSettings {
  double similarity_threshold = 0.7;  // (paper) zeta below this makes a keyframe
  int pyramid_levels = 4;             // (paper) levels encoded, as the feature pyramid
  double scale_factor = 1.2;          // (paper)
  uint64_t pattern_seed = 2025;  // (slamkit) fixes the random pixel of every 2x2 window for a run
  int neighbour_frames = 1;  // (slamkit) frames on each side of the latest keyframe also compared
  // (slamkit) Guard: a frame whose tracked matches fall below this share of those its reference
  // keyframe had becomes a keyframe whatever zeta says, so the map never thins out.
  double min_tracked_ratio = 0.5;
};

}  // namespace slamkit
