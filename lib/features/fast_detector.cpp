#include "features/fast_detector.h"

#include <algorithm>
#include <array>
#include <opencv2/features2d.hpp>

namespace slamkit {
namespace {

// The Bresenham circle of radius 3, clockwise from pixel 1 straight above the centre.
constexpr std::array<std::array<int, 2>, 16> kCircle = {{{0, -3},
                                                         {1, -3},
                                                         {2, -2},
                                                         {3, -1},
                                                         {3, 0},
                                                         {3, 1},
                                                         {2, 2},
                                                         {1, 3},
                                                         {0, 3},
                                                         {-1, 3},
                                                         {-2, 2},
                                                         {-3, 1},
                                                         {-3, 0},
                                                         {-3, -1},
                                                         {-2, -2},
                                                         {-1, -3}}};

// Longest circular run of `true` in the 16 flags.
int longest_circular_run(const std::array<bool, 16>& flags) {
  int best = 0, run = 0;
  for (int i = 0; i < 32; ++i) {  // twice round, so runs across pixel 16 -> 1 count
    run = flags[i % 16] ? run + 1 : 0;
    best = std::max(best, std::min(run, 16));
  }
  return best;
}

}  // namespace

bool passes_fast12(const cv::Mat& image, cv::Point p, int threshold) {
  const int centre = image.at<uchar>(p);
  std::array<bool, 16> brighter{}, darker{};
  for (int i = 0; i < 16; ++i) {
    const int v = image.at<uchar>(p.y + kCircle[i][1], p.x + kCircle[i][0]);
    brighter[i] = v > centre + threshold;  // strict, as OpenCV's FAST
    darker[i] = v < centre - threshold;
  }
  // Quick test: 12 contiguous pixels always cover at least 3 of the compass pixels 1, 5, 9, 13.
  int quick_bright = 0, quick_dark = 0;
  for (int i : {0, 4, 8, 12}) quick_bright += brighter[i], quick_dark += darker[i];
  if (quick_bright < 3 && quick_dark < 3) return false;
  return longest_circular_run(brighter) >= 12 || longest_circular_run(darker) >= 12;
}

std::vector<cv::Point> detect_fast(const cv::Mat& image, const cv::Rect& region, int threshold,
                                   FastType type) {
  // cv::FAST skips 3 px at the border of what it is given: hand it the region grown by 3.
  const cv::Rect grown = cv::Rect(region.x - 3, region.y - 3, region.width + 6, region.height + 6) &
                         cv::Rect(0, 0, image.cols, image.rows);
  std::vector<cv::KeyPoint> found;
  // OpenCV has no FAST-12 on 16 pixels. Every FAST-12 corner is a FAST-9 corner at the same
  // threshold, so FAST-12 = OpenCV's TYPE_9_16 candidates filtered by the 12-pixel test.
  cv::FAST(image(grown), found, threshold, false, cv::FastFeatureDetector::TYPE_9_16);
  std::vector<cv::Point> corners;
  corners.reserve(found.size());
  for (const cv::KeyPoint& k : found) {
    const cv::Point p(cvRound(k.pt.x) + grown.x, cvRound(k.pt.y) + grown.y);
    if (!region.contains(p)) continue;
    if (type == FastType::kFast12 && !passes_fast12(image, p, threshold)) continue;
    corners.push_back(p);
  }
  // cv::FAST scans row by row, so the order is raster already; sorting is the fallback.
  const auto raster_less = [](const cv::Point& a, const cv::Point& b) {
    return a.y != b.y ? a.y < b.y : a.x < b.x;
  };
  if (!std::is_sorted(corners.begin(), corners.end(), raster_less)) {
    std::sort(corners.begin(), corners.end(), raster_less);
  }
  return corners;
}

}  // namespace slamkit
