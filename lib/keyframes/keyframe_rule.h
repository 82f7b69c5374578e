#pragma once
// The keyframe rule (docs/method.md#keyframes): the current frame is compared with the latest
// keyframe and its neighbour frames; if the least similar of them has zeta < 0.7 the frame is a
// keyframe. A guard (ours) also makes one when tracking thins out.
#include <vector>

#include "core/settings/keyframe_settings.h"
#include "keyframes/window_code.h"

namespace slamkit {

struct KeyframeDecision {
  bool is_keyframe = false;
  double similarity = 1.0;  // zeta_I, the minimum over the compared frames
  bool forced_by_tracking = false;
};

// `compared` holds the codes of the latest keyframe and its neighbour frames (see
// keyframe_neighbours). tracked_matches is how many of the current frame's features were
// matched to the map; reference_matches how many its reference keyframe had (0: no guard).
KeyframeDecision decide_keyframe(const WindowCode& current,
                                 const std::vector<const WindowCode*>& compared,
                                 int tracked_matches, int reference_matches,
                                 const KeyframeSettings& settings);

// Indices of the frames the current one is compared with: the latest keyframe and
// settings.neighbour_frames frames on each side of it, all before `current`.
std::vector<size_t> keyframe_neighbours(size_t latest_keyframe, size_t current,
                                        const KeyframeSettings& settings);

}  // namespace slamkit
