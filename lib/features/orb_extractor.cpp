#include "features/orb_extractor.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "features/cell_grid.h"
#include "features/descriptor.h"
#include "features/equivalent_grey.h"
#include "features/fast_detector.h"
#include "features/keypoint_selection.h"
#include "features/orientation.h"

namespace slamkit {
namespace {

constexpr float kPatchSize = 31.0f;  // ORB's patch, for cv::KeyPoint::size

// Low-texture cells get a second chance at the lower threshold (ORB-SLAM2's retry): the corners
// found there, in cells where `strong` has none. The segment test reads only the circle around
// a pixel, so one FAST call over a run of empty cells in a grid row finds what a call per cell
// would, with less overhead per call.
std::vector<cv::Point> retry_empty_cells(const cv::Mat& level, const std::vector<cv::Point>& strong,
                                         const CellGrid& grid, const OrbSettings& settings) {
  std::vector<bool> empty(grid.count(), true);
  for (const cv::Point& p : strong) empty[grid.index_of(p)] = false;
  std::vector<cv::Point> weak;
  for (int c = 0; c < grid.count();) {
    if (!empty[c]) {
      ++c;
      continue;
    }
    const int row_end = (c / grid.cols + 1) * grid.cols;
    int last = c;
    while (last + 1 < row_end && empty[last + 1]) ++last;
    const std::vector<cv::Point> found = detect_fast(
        level, grid.cell(c) | grid.cell(last), settings.fast_min_threshold, settings.fast_type);
    weak.insert(weak.end(), found.begin(), found.end());
    c = last + 1;
  }
  return weak;
}

// Up to `quota` corners of one level image, chosen by Shi-Tomasi, in level pixels.
std::vector<Corner> detect_level(const cv::Mat& level, int quota, const OrbSettings& settings) {
  const int edge = settings.edge_threshold;
  const cv::Rect region(edge, edge, level.cols - 2 * edge, level.rows - 2 * edge);
  if (region.width <= 0 || region.height <= 0 || quota <= 0) return {};

  const std::vector<cv::Point> strong =
      detect_fast(level, region, settings.fast_threshold, settings.fast_type);
  const CellGrid grid = CellGrid::over(region, settings.cell_size);
  std::vector<cv::Point> candidates = strong;  // the strong ones first, then the retry's
  if (settings.spread_over_image) {
    const std::vector<cv::Point> weak = retry_empty_cells(level, strong, grid, settings);
    candidates.insert(candidates.end(), weak.begin(), weak.end());
  }
  // Suppression over all candidates, so a weak corner cannot sit next to a strong one.
  const std::vector<Corner> ranked = suppress_non_maxima(
      candidates, shi_tomasi_response(level, candidates, settings.shi_tomasi_block_size),
      level.size());
  if (!settings.spread_over_image) return select_strongest(ranked, quota);

  // Corners of the lower threshold only fill what the others leave: in a textured scene they
  // would displace more repeatable corners (measured on fr1/fr2 desk).
  std::vector<Corner> first, second;
  for (const Corner& c : ranked) {
    (c.candidate < static_cast<int>(strong.size()) ? first : second).push_back(c);
  }
  std::vector<Corner> chosen = select_spread(first, quota, grid, settings.max_cell_share);
  const std::vector<Corner> fill =
      select_spread(second, quota - static_cast<int>(chosen.size()), grid, settings.max_cell_share);
  chosen.insert(chosen.end(), fill.begin(), fill.end());
  return chosen;
}

}  // namespace

FrameFeatures extract_orb(const cv::Mat& image, const Camera& camera, const OrbSettings& settings) {
  // The orientation disc and the Shi-Tomasi window are read without bounds checks.
  if (settings.edge_threshold <
      std::max(kOrientationRadius, settings.shi_tomasi_block_size / 2 + 1)) {
    throw std::invalid_argument("extract_orb: edge_threshold smaller than the patches it guards");
  }
  FrameFeatures features;
  features.pyramid =
      build_pyramid(equivalent_grey(image), settings.pyramid_levels, settings.scale_factor);
  const ImagePyramid& pyramid = features.pyramid;
  const std::vector<int> quota =
      features_per_level(settings.num_features, pyramid.size(), settings.scale_factor);

  std::vector<cv::Mat> level_descriptors;
  int unused = 0;  // what a level could not fill passes to the next (coarser) one
  for (int l = 0; l < pyramid.size(); ++l) {
    const cv::Mat& level = pyramid.levels[l];
    const std::vector<Corner> corners = detect_level(level, quota[l] + unused, settings);
    unused += quota[l] - static_cast<int>(corners.size());

    std::vector<cv::KeyPoint> at_level;
    at_level.reserve(corners.size());
    for (const Corner& c : corners) {
      at_level.emplace_back(cv::Point2f(c.pt), kPatchSize * static_cast<float>(pyramid.scales[l]),
                            intensity_centroid_angle(level, c.pt), c.response, l);
    }
    level_descriptors.push_back(steered_brief(level, at_level));
    for (cv::KeyPoint& k : at_level) {
      k.pt = pyramid.to_level0(k.pt, l);
      features.keypoints.push_back(k);
    }
  }

  features.descriptors.create(static_cast<int>(features.keypoints.size()), kDescriptorBytes, CV_8U);
  int row = 0;
  for (const cv::Mat& d : level_descriptors) {
    if (d.empty()) continue;  // copyTo from an empty Mat would release the fixed-size rows
    d.copyTo(features.descriptors.rowRange(row, row + d.rows));
    row += d.rows;
  }

  std::vector<Eigen::Vector2d> raw(features.keypoints.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    raw[i] = {features.keypoints[i].pt.x, features.keypoints[i].pt.y};
  }
  features.undistorted = camera.undistort_pixels(raw);
  return features;
}

}  // namespace slamkit
