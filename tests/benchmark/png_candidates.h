#pragma once
// The PNG decoders the decode benchmark compares, each returning read_png's layout (BGR,
// 16-bit samples in host order). Optional libraries found at configure time add theirs.
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace slamkit::bench {

struct PngCandidate {
  std::string name;
  std::function<cv::Mat(const std::filesystem::path&)> decode;
};

// libpng first: the reference the others must match pixel for pixel.
std::vector<PngCandidate> png_candidates();

}  // namespace slamkit::bench
