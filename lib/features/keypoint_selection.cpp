#include "features/keypoint_selection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace slamkit {
namespace {

bool stronger(const Corner& a, const Corner& b) {
  if (a.response != b.response) return a.response > b.response;
  return a.pt.y != b.pt.y ? a.pt.y < b.pt.y : a.pt.x < b.pt.x;
}

}  // namespace

std::vector<float> shi_tomasi_response(const cv::Mat& grey, const std::vector<cv::Point>& points,
                                       int block_size) {
  if (block_size < 1 || block_size > kMaxShiTomasiBlock || block_size % 2 == 0) {
    throw std::invalid_argument("shi_tomasi_response: the block size must be odd, 1 to " +
                                std::to_string(kMaxShiTomasiBlock));
  }
  // OpenCV does the image filtering: spatialGradient gives both 3x3 Sobel derivatives (the
  // values and BORDER_REFLECT_101 of cv::Sobel) in one pass. It writes into views of buffers 8
  // columns wider, so the 8-lane loads below never leave the buffer.
  // The buffers stay with the thread: fresh ones cost page faults on every level of every frame.
  constexpr int kLanes = 8;
  thread_local cv::Mat dx_buffer, dy_buffer;
  if (dx_buffer.rows < grey.rows || dx_buffer.cols < grey.cols + kLanes) {
    dx_buffer.create(grey.rows, grey.cols + kLanes, CV_16S);
    dy_buffer.create(grey.rows, grey.cols + kLanes, CV_16S);
  }
  cv::Mat dx = dx_buffer(cv::Rect(0, 0, grey.cols, grey.rows));
  cv::Mat dy = dy_buffer(cv::Rect(0, 0, grey.cols, grey.rows));
  cv::spatialGradient(grey, dx, dy, 3);
  if (dx.datastart != dx_buffer.datastart || dy.datastart != dy_buffer.datastart) {
    throw std::logic_error("shi_tomasi_response: cv::spatialGradient reallocated its output");
  }
  // The sparse window sums are ours (the paper vectorises the corner response), on OpenCV's
  // portable SIMD: 8 derivatives per load, lanes past the window masked off. Integer sums, so
  // the result is exact whatever the instruction set.
  const int chunks = (block_size + kLanes - 1) / kLanes;
  std::vector<cv::v_int16x8> masks(chunks);
  for (int c = 0; c < chunks; ++c) {
    short lanes[kLanes];
    for (int i = 0; i < kLanes; ++i) lanes[i] = c * kLanes + i < block_size ? -1 : 0;
    masks[c] = cv::v_load(lanes);
  }
  // cv::cornerMinEigenVal scales the derivatives by 1 / (4 * block_size * 255).
  const double scale = 1.0 / (4.0 * block_size * 255.0);
  const int r = block_size / 2;
  std::vector<float> responses(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    cv::v_int32x4 xx = cv::v_setzero_s32(), yy = xx, xy = xx;
    for (int v = points[i].y - r; v <= points[i].y + r; ++v) {
      const short* gx = dx.ptr<short>(v) + points[i].x - r;
      const short* gy = dy.ptr<short>(v) + points[i].x - r;
      for (int c = 0; c < chunks; ++c) {
        const cv::v_int16x8 a = cv::v_load(gx + c * kLanes) & masks[c];
        const cv::v_int16x8 b = cv::v_load(gy + c * kLanes) & masks[c];
        xx += cv::v_dotprod(a, a), yy += cv::v_dotprod(b, b), xy += cv::v_dotprod(a, b);
      }
    }
    const double a = 0.5 * cv::v_reduce_sum(xx), c = 0.5 * cv::v_reduce_sum(yy);
    const double b = cv::v_reduce_sum(xy);
    responses[i] =
        static_cast<float>(((a + c) - std::sqrt((a - c) * (a - c) + b * b)) * scale * scale);
  }
  return responses;
}

std::vector<Corner> suppress_non_maxima(const std::vector<cv::Point>& candidates,
                                        const std::vector<float>& responses, cv::Size image_size) {
  constexpr float kNone = -std::numeric_limits<float>::infinity();  // never suppresses anything
  // Candidate responses on a map with a one-pixel margin, so every 8-neighbour can be read
  // without a bounds check. Filling a fresh full-size map took longer than the suppression
  // itself, so each thread keeps one, all kNone between calls (reset below).
  thread_local cv::Mat map;
  if (map.rows < image_size.height + 2 || map.cols < image_size.width + 2) {
    map.create(std::max(map.rows, image_size.height + 2), std::max(map.cols, image_size.width + 2),
               CV_32F);
    map.setTo(kNone);
  }
  cv::Mat scores = map(cv::Rect(1, 1, image_size.width, image_size.height));
  for (size_t i = 0; i < candidates.size(); ++i) scores.at<float>(candidates[i]) = responses[i];
  const size_t step = scores.step1();
  std::vector<Corner> kept;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const float* at = scores.ptr<float>(candidates[i].y) + candidates[i].x;
    const float* above = at - step;
    const float* below = at + step;
    const float r = *at;
    // All eight comparisons, no early exit: the branch would be a coin toss. Equal responses:
    // the earlier in raster order stays (the row above, and the left neighbour).
    const bool is_max = (above[-1] < r) & (above[0] < r) & (above[1] < r) & (at[-1] < r) &
                        (at[1] <= r) & (below[-1] <= r) & (below[0] <= r) & (below[1] <= r);
    if (is_max) kept.push_back({candidates[i], r, static_cast<int>(i)});
  }
  for (const cv::Point& p : candidates) scores.at<float>(p) = kNone;
  std::sort(kept.begin(), kept.end(),
            [](const Corner& a, const Corner& b) { return stronger(a, b); });
  return kept;
}

std::vector<int> features_per_level(int total, int num_levels, double scale_factor) {
  std::vector<double> weight(num_levels);
  double sum = 0;
  for (int l = 0; l < num_levels; ++l) sum += weight[l] = std::pow(scale_factor, -2.0 * l);
  std::vector<int> counts(num_levels);
  int given = 0;
  for (int l = 0; l + 1 < num_levels; ++l) given += counts[l] = cvRound(total * weight[l] / sum);
  counts[num_levels - 1] = std::max(0, total - given);
  return counts;
}

std::vector<Corner> select_strongest(const std::vector<Corner>& sorted, int n) {
  return {sorted.begin(), sorted.begin() + std::min<size_t>(sorted.size(), std::max(0, n))};
}

std::vector<Corner> select_spread(const std::vector<Corner>& sorted, int n, const CellGrid& grid,
                                  double max_share) {
  std::vector<int> in_cell(grid.count(), 0);
  for (const Corner& c : sorted) ++in_cell[grid.index_of(c.pt)];
  const int occupied =
      static_cast<int>(std::count_if(in_cell.begin(), in_cell.end(), [](int k) { return k > 0; }));
  if (occupied == 0 || n <= 0) return {};
  // The cap is at least 1, so every occupied cell can give its best corner.
  const int cap = std::max(1, static_cast<int>(std::ceil(max_share * n / occupied)));
  std::vector<int> taken(grid.count(), 0);
  std::vector<Corner> chosen;
  for (const Corner& c : sorted) {
    if (static_cast<int>(chosen.size()) == n) break;
    int& t = taken[grid.index_of(c.pt)];
    if (t < cap) ++t, chosen.push_back(c);
  }
  return chosen;
}

}  // namespace slamkit
