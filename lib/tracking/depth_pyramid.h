#pragma once
// Depth images at halved resolutions, for coarse-to-fine dense alignment.
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"

namespace slamkit {

// Halves a CV_32F depth image (metres, 0 = no measurement). Each output pixel is the lower
// median of the valid (> 0) depths of its 2x2 block, so it is always a depth that was
// measured: averaging would invent surfaces between a foreground edge and the background.
// 0 when no pixel of the block is valid. Odd trailing rows/columns are dropped.
cv::Mat downsample_depth(const cv::Mat& depth);

// levels images: [0] is depth itself, [l] is [l-1] downsampled.
std::vector<cv::Mat> depth_pyramid(const cv::Mat& depth, int levels);

// The camera of pyramid level `level`: focal lengths halved per level, principal point
// moved with the 2x2 block centres ((c + 0.5) / 2 - 0.5), size halved.
Camera camera_at_level(const Camera& camera, int level);

}  // namespace slamkit
