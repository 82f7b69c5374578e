#pragma once
// Keypoint orientation by the intensity centroid (docs/method.md#features).
#include <opencv2/core.hpp>
#include <vector>

namespace slamkit {

// Radius of ORB's circular orientation patch (half of its 31-pixel patch).
constexpr int kOrientationRadius = 15;

// Half-width of ORB's circular patch on rows 0..radius from the centre.
std::vector<int> disc_half_widths(int radius);

// theta = atan2(m01, m10) with m_pq = sum x^p y^q I(x, y) over ORB's disc of `radius` around
// `centre` (x right, y down, as cv::KeyPoint::angle). Degrees in [0, 360). Written here: OpenCV
// computes it only inside cv::ORB. The disc must lie inside the image.
float intensity_centroid_angle(const cv::Mat& grey, cv::Point centre,
                               int radius = kOrientationRadius);

}  // namespace slamkit
