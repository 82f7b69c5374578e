#pragma once
// The parallel stage of the batch engine: decode, ORB features and window code of many frames
// at once. Results do not depend on the thread count.
#include <vector>

#include "core/settings/settings.h"
#include "io/tum_sequence.h"
#include "keyframes/window_code.h"
#include "tracking/prepared_frame.h"

namespace slamkit {

// Frames [begin, end) of the sequence, in order. Rethrows the first InputError (by frame
// order) after the parallel loop, so a bad file is reported the same way at any thread count.
std::vector<PreparedFrame> prepare_frames(const TumSequence& sequence, size_t begin, size_t end,
                                          const Settings& settings, const WindowPattern& pattern);

}  // namespace slamkit
