#pragma once
// The frames of a fusion, a batch at a time: their samples (kept from tracking, or loaded from
// the sequence again) handed to work on the OpenMP threads.
#include <functional>
#include <vector>

#include "fusion/map_fusion.h"

namespace slamkit {

// Calls work(i, samples) for frames[first .. first + count) in parallel, each i once. An error
// (an unreadable frame, or thrown by work) is rethrown as InputError after the batch: the
// earliest failing frame's, whatever the threads.
void for_frames_in_parallel(const TumSequence& sequence, const std::vector<FusionFrame>& frames,
                            size_t first, size_t count, int pixel_stride,
                            const std::function<void(size_t, const FusionSamples&)>& work);

}  // namespace slamkit
