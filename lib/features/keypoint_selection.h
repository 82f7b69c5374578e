#pragma once
// Ranking and choosing FAST corners by their Shi-Tomasi response (docs/method.md#features).
#include <opencv2/core.hpp>
#include <vector>

#include "features/cell_grid.h"

namespace slamkit {

struct Corner {
  cv::Point pt;
  float response = 0;
  int candidate = -1;  // index in the candidate list it was chosen from
};

// Shi-Tomasi response (smaller eigenvalue of the structure tensor of 3x3 Sobel derivatives over
// block_size x block_size) at each point, scaled as cv::cornerMinEigenVal, which computes it at
// every pixel; here only the candidates pay (a few thousand of 300,000 pixels). Points must lie
// at least block_size / 2 + 1 px inside the image; block_size is odd and at most
// kMaxShiTomasiBlock (the 32-bit window sums would overflow beyond).
constexpr int kMaxShiTomasiBlock = 31;
std::vector<float> shi_tomasi_response(const cv::Mat& grey, const std::vector<cv::Point>& points,
                                       int block_size);

// Candidates with their responses, keeping only those no 8-neighbour candidate beats (equal
// responses: the first in raster order stays). Sorted strongest first (ties by position).
std::vector<Corner> suppress_non_maxima(const std::vector<cv::Point>& candidates,
                                        const std::vector<float>& responses, cv::Size image_size);

// How many of `total` features each level gets: proportional to the level's area
// (n_l ~ scale_factor^-2l, as ORB-SLAM2), summing to total.
std::vector<int> features_per_level(int total, int num_levels, double scale_factor);

// The first n of corners sorted strongest first.
std::vector<Corner> select_strongest(const std::vector<Corner>& sorted, int n);

// Up to n corners, strongest first, but no grid cell keeps more than max_share times its fair
// share n / (cells holding a corner), so one textured spot cannot take all n (written here: no
// library does it). Keeps the order of `sorted`.
std::vector<Corner> select_spread(const std::vector<Corner>& sorted, int n, const CellGrid& grid,
                                  double max_share);

}  // namespace slamkit
