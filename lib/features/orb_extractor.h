#pragma once
// ORB extraction of one frame: the recipe of docs/method.md#features.
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/settings/orb_settings.h"
#include "features/frame_features.h"

namespace slamkit {

// `image` is BGR (CV_8UC3, as TumSequence loads it; detection runs on its equivalent grey) or
// grey (CV_8UC1). Deterministic: the same image and settings give the same features bit for
// bit, on any thread.
FrameFeatures extract_orb(const cv::Mat& image, const Camera& camera, const OrbSettings& settings);

}  // namespace slamkit
