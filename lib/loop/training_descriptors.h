#pragma once
// The training images of a vocabulary: ORB descriptors of a sequence's frames, extracted as
// tracking extracts them (docs/method.md#features), so the words fit the features they will
// index.
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/orb_settings.h"
#include "io/tum_sequence.h"

namespace slamkit {

// One descriptor matrix (CV_8U, n x 32) per frame 0, step, 2 step, ... of the sequence, in
// frame order; frames are decoded and extracted in parallel (OpenMP), the result the same at
// any thread count. Throws InputError for a frame that cannot be read.
std::vector<cv::Mat> sequence_descriptors(const TumSequence& sequence, const OrbSettings& orb,
                                          int frame_step);

}  // namespace slamkit
