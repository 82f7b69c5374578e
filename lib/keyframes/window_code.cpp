#include "keyframes/window_code.h"

#include <bitset>
#include <cmath>
#include <random>
#include <stdexcept>

namespace slamkit {

WindowPattern::WindowPattern(cv::Size image_size, const KeyframeSettings& settings) {
  std::mt19937_64 rng(settings.pattern_seed);
  std::uniform_int_distribution<int> pick(0, 3);
  for (int level = 0; level < settings.pyramid_levels; ++level) {
    const double scale = std::pow(settings.scale_factor, -level);
    // Same rounding as cv::resize's destination size for the feature pyramid.
    const cv::Size size(int(std::round(image_size.width * scale)),
                        int(std::round(image_size.height * scale)));
    level_sizes_.push_back(size);
    std::vector<uint8_t> choices(size_t(size.width / 2) * (size.height / 2));
    for (uint8_t& c : choices) c = uint8_t(pick(rng));
    total_bits_ += choices.size();
    choices_.push_back(std::move(choices));
  }
}

uint8_t WindowPattern::choice(int level, int wx, int wy) const {
  return choices_[level][size_t(wy) * (level_sizes_[level].width / 2) + wx];
}

bool fits(const ImagePyramid& grey, const WindowPattern& pattern) {
  if (grey.size() < pattern.levels()) return false;
  for (int level = 0; level < pattern.levels(); ++level)
    if (grey.levels[level].size() != pattern.level_size(level)) return false;
  return true;
}

WindowCode encode_windows(const ImagePyramid& grey, const WindowPattern& pattern, double tau) {
  if (!fits(grey, pattern) || grey.levels[0].type() != CV_8UC1)
    throw std::invalid_argument("encode_windows: the pyramid does not fit the window pattern");
  if (tau < 0) tau = cv::mean(grey.levels[0])[0];

  WindowCode code;
  code.bits = pattern.total_bits();
  code.words.assign((code.bits + 63) / 64, 0);
  size_t bit = 0;
  for (int level = 0; level < pattern.levels(); ++level) {
    const cv::Mat& level_image = grey.levels[level];
    const int windows_x = level_image.cols / 2, windows_y = level_image.rows / 2;
    for (int wy = 0; wy < windows_y; ++wy) {
      const uchar* rows[2] = {level_image.ptr<uchar>(2 * wy), level_image.ptr<uchar>(2 * wy + 1)};
      for (int wx = 0; wx < windows_x; ++wx, ++bit) {
        const uint8_t c = pattern.choice(level, wx, wy);
        // Branch-free: on image data the comparison is a coin toss the predictor cannot learn.
        const uint64_t set = rows[c >> 1][2 * wx + (c & 1)] >= tau;
        code.words[bit >> 6] |= set << (bit & 63);
      }
    }
  }
  return code;
}

double window_similarity(const WindowCode& a, const WindowCode& b) {
  if (a.bits != b.bits || a.bits == 0)
    throw std::invalid_argument("window_similarity: codes of different patterns");
  size_t distance = 0;
  for (size_t i = 0; i < a.words.size(); ++i)
    distance += std::bitset<64>(a.words[i] ^ b.words[i]).count();
  return 1.0 - double(distance) / double(a.bits);
}

}  // namespace slamkit
