#pragma once
// Image sharpness: motion blur and defocus remove high frequencies, which the Laplacian sees.
#include <opencv2/core.hpp>

namespace slamkit::stats {

// Variance of the Laplacian (3x3 aperture) of the grey image, in grey levels^2. `image` is
// BGR (CV_8UC3) or grey (CV_8UC1). It also grows with the scene's texture, so compare frames
// of one scene, or sequences of similar scenes.
double laplacian_variance(const cv::Mat& image);

}  // namespace slamkit::stats
