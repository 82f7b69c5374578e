#pragma once
// ORB features of many frames at once: the batch engine's parallel extraction
// (docs/method.md#features).
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "core/settings/orb_settings.h"
#include "features/frame_features.h"

namespace slamkit {

// extract_orb() on every image in parallel with OpenMP; result i belongs to images[i] and is
// the same at any thread count. num_threads <= 0 uses OpenMP's default.
std::vector<FrameFeatures> extract_orb_batch(const std::vector<cv::Mat>& images,
                                             const Camera& camera, const OrbSettings& settings,
                                             int num_threads = 0);

}  // namespace slamkit
