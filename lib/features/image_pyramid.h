#pragma once
// The grey image pyramid ORB detects on, kept for the tracker (dense alignment reuses it).
#include <opencv2/core.hpp>
#include <vector>

namespace slamkit {

struct ImagePyramid {
  std::vector<cv::Mat> levels;  // CV_8UC1; level 0 is the full-resolution grey image
  std::vector<double> scales;   // nominal scale_factor^l: search radii and noise grow with it

  int size() const { return static_cast<int>(levels.size()); }

  // Exact pixel mapping between a level and level 0. Level sizes are rounded, so the true ratio
  // differs slightly from scales[l] per axis; cv::resize maps pixel centres, hence the 0.5.
  cv::Point2f to_level0(const cv::Point2f& p, int level) const;
  cv::Point2f from_level0(const cv::Point2f& p, int level) const;
};

// Level l is round(size / scale_factor^l), each area-averaged from level 0 (the paper's
// INTER_AREA, see area_downscale.h).
ImagePyramid build_pyramid(const cv::Mat& grey, int num_levels, double scale_factor);

}  // namespace slamkit
