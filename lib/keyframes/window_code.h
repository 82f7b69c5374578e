#pragma once
// Random window encoding (docs/method.md#keyframes): every pyramid level is cut into
// 2x2-pixel windows; one pixel per window, drawn once per run, is compared with a threshold tau
// and gives one bit. Similar codes mean similar views; the keyframe rule compares them.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/keyframe_settings.h"
#include "features/image_pyramid.h"

namespace slamkit {

// Which of the 4 pixels of each window is read, per level. Fixed for the whole run.
class WindowPattern {
 public:
  WindowPattern(cv::Size image_size, const KeyframeSettings& settings);

  int levels() const { return int(level_sizes_.size()); }
  cv::Size level_size(int level) const { return level_sizes_[level]; }
  // Offset (0..3 = dx + 2 dy) of the chosen pixel in window (wx, wy) of a level.
  uint8_t choice(int level, int wx, int wy) const;
  size_t total_bits() const { return total_bits_; }

 private:
  std::vector<cv::Size> level_sizes_;
  std::vector<std::vector<uint8_t>> choices_;  // per level, row-major over windows
  size_t total_bits_ = 0;
};

// The bit code of one frame: all levels' bits packed into 64-bit words.
struct WindowCode {
  std::vector<uint64_t> words;
  size_t bits = 0;
};

// Encodes a frame from the area-averaged pyramid of its equivalent grey (R + G + B) / 3, whose
// first levels must have the pattern's sizes (the feature pyramid does when the keyframe and
// ORB settings agree on levels and scale). tau is level 0's mean unless given. Throws
// std::invalid_argument when the pyramid does not fit the pattern.
WindowCode encode_windows(const ImagePyramid& grey, const WindowPattern& pattern,
                          double tau = -1.0);

// Whether `grey` has the pattern's level sizes, for encode_windows.
bool fits(const ImagePyramid& grey, const WindowPattern& pattern);

// zeta = 1 - Hamming(a, b) / n.
double window_similarity(const WindowCode& a, const WindowCode& b);

}  // namespace slamkit
