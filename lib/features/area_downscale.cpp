#include "features/area_downscale.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace slamkit {
namespace {

// Written here because cv::resize takes a scalar floating-point path for INTER_AREA at a
// non-integer ratio such as 1.2: shrinking 640x480 to 533x400 measured 1.9-2.3 ms with it,
// 0.7-0.9 ms with these integer passes; the pyramid was the largest single cost of ORB
// extraction.

// 15-bit weights: a weight and a grey level both fit 16 bits, so the vertical pass is a
// 16 x 16 -> 32-bit multiply the compiler vectorises with SSE2; the horizontal sums are 64-bit.
constexpr int kWeightBits = 15;
constexpr uint32_t kOne = 1u << kWeightBits;

// The source pixels each output pixel covers along one axis: out x stride weights (zero-padded),
// starting at first[j].
struct Taps {
  int stride = 0;
  std::vector<int> first;
  std::vector<uint16_t> weights;
};

// Output pixel j covers the source interval [j s, (j + 1) s) with s = in / out; a source pixel
// weighs its overlap with that interval over s.
Taps area_taps(int in, int out) {
  const double s = static_cast<double>(in) / out;
  Taps taps;
  taps.stride = static_cast<int>(std::ceil(s)) + 1;
  taps.first.resize(out);
  taps.weights.assign(static_cast<size_t>(out) * taps.stride, 0);
  for (int j = 0; j < out; ++j) {
    const double begin = j * s, end = std::min<double>(in, (j + 1) * s);
    taps.first[j] = static_cast<int>(std::floor(begin));
    uint16_t* w = &taps.weights[static_cast<size_t>(j) * taps.stride];
    uint32_t sum = 0;
    int largest = 0;
    for (int i = taps.first[j], k = 0; i < end; ++i, ++k) {
      const double overlap = std::min<double>(i + 1, end) - std::max<double>(i, begin);
      w[k] = static_cast<uint16_t>(std::lround(overlap / s * kOne));
      sum += w[k];
      if (w[k] > w[largest]) largest = k;
    }
    w[largest] = static_cast<uint16_t>(w[largest] + kOne - sum);  // the weights sum to one
  }
  return taps;
}

// One output row from the column sums. kStride > 0 fixes the taps at compile time, which
// unrolls the inner loop: the pyramid's ratios (up to 2) all have 3, and this pass is the
// costly one (it gathers, where the vertical pass streams).
template <int kStride>
void horizontal_pass(const uint32_t* column_sums, const Taps& across, uchar* out, int width) {
  const int stride = kStride > 0 ? kStride : across.stride;
  for (int x = 0; x < width; ++x) {
    const uint16_t* w = &across.weights[static_cast<size_t>(x) * stride];
    const uint32_t* sums = column_sums + across.first[x];
    uint64_t sum = 0;
    for (int k = 0; k < stride; ++k) sum += static_cast<uint64_t>(w[k]) * sums[k];
    out[x] =
        static_cast<uchar>((sum + (uint64_t{1} << (2 * kWeightBits - 1))) >> (2 * kWeightBits));
  }
}

}  // namespace

cv::Mat area_downscale(const cv::Mat& grey, cv::Size size) {
  if (grey.type() != CV_8UC1) throw std::invalid_argument("area_downscale: needs CV_8UC1");
  if (size.width < 1 || size.height < 1 || size.width > grey.cols || size.height > grey.rows) {
    throw std::invalid_argument("area_downscale: the size must be within the image's");
  }
  const Taps across = area_taps(grey.cols, size.width);
  const Taps down = area_taps(grey.rows, size.height);
  // A zero weight may point one row or column past the image: pad the sums, skip such rows.
  std::vector<uint32_t> column_sums(grey.cols + across.stride, 0u);
  cv::Mat shrunk(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    std::fill(column_sums.begin(), column_sums.end(), 0u);
    for (int k = 0; k < down.stride; ++k) {
      const uint16_t w = down.weights[static_cast<size_t>(y) * down.stride + k];
      if (w == 0) continue;
      const uchar* source = grey.ptr<uchar>(down.first[y] + k);
      for (int x = 0; x < grey.cols; ++x) {
        column_sums[x] += static_cast<uint32_t>(w) * static_cast<uint16_t>(source[x]);
      }
    }
    uchar* out = shrunk.ptr<uchar>(y);
    if (across.stride == 3) {
      horizontal_pass<3>(column_sums.data(), across, out, size.width);  // ratios up to 2
    } else {
      horizontal_pass<0>(column_sums.data(), across, out, size.width);
    }
  }
  return shrunk;
}

}  // namespace slamkit
