#pragma once
// PNG files through libpng, the only image format of TUM sequences. Not OpenCV's imgcodecs:
// on Debian it drags ~140 shared libraries (GDAL and more) into every process, which costs
// 0.2-0.3 s at each start of the command line tool, for a format libpng reads alone.
#include <filesystem>
#include <opencv2/core.hpp>

namespace slamkit {

// What read_png accepts, checked on the header before any pixel memory is taken, so that a
// header claiming a huge image is an error instead of an out-of-memory kill. A TUM frame is
// 640x480 (1.2 MB as 16-bit depth); these leave room for any RGB-D sensor.
constexpr int kMaxImageSide = 16384;
constexpr size_t kMaxImageBytes = size_t(256) << 20;  // decoded

// Decodes as stored: 8-bit grey CV_8UC1, colour CV_8UC3 (BGR, as OpenCV), with alpha
// CV_8UC4 (BGRA), 16-bit grey CV_16UC1 (values exact), 16-bit colour CV_16UC3. Palette and
// sub-8-bit images are expanded to 8 bits. Throws InputError naming the file, also for an image
// beyond kMaxImageSide or kMaxImageBytes.
cv::Mat read_png(const std::filesystem::path& path);

// Encodes CV_8UC1, CV_8UC3 (BGR), CV_8UC4 (BGRA) or CV_16UC1. compression 0-9; the
// run-length strategy suits noisy sensor images. Throws InputError naming the file.
void write_png(const std::filesystem::path& path, const cv::Mat& image, int compression = 1);

}  // namespace slamkit
