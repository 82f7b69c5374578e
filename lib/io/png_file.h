#pragma once
// PNG files, the only image format of TUM sequences. Not OpenCV's imgcodecs: on Debian it
// drags ~140 shared libraries (GDAL and more) into every process, which costs 0.2-0.3 s at
// each start of the command line tool, for a format these libraries read alone.
#include <filesystem>
#include <opencv2/core.hpp>

namespace slamkit {

// Images larger than these are refused: a header can claim any size (a 74-byte file claimed
// 60000 x 60000 pixels, 7.2 GB), and no RGB-D sensor comes near them.
constexpr int kMaxImageSide = 16384;
constexpr size_t kMaxImageBytes = size_t(256) << 20;  // decoded

// Decodes as stored: 8-bit grey CV_8UC1, colour CV_8UC3 (BGR, as OpenCV), with alpha
// CV_8UC4 (BGRA), 16-bit grey CV_16UC1 (values exact), 16-bit colour CV_16UC3/CV_16UC4.
// Palette and sub-8-bit images are expanded to 8 bits. The common layouts (8- and 16-bit
// grey, RGB, RGBA, not interlaced) are inflated by ISA-L and unfiltered here
// (io/png_unfilter.h), over twice as fast as libpng and pixel-identical to it (tests/io,
// tests/benchmark/png_decode_benchmark); libpng decodes the rest. Throws InputError naming the file, also for an image beyond
// kMaxImageSide or kMaxImageBytes (checked on the header, before any pixel memory).
cv::Mat read_png(const std::filesystem::path& path);

// The same through libpng alone: the reference read_png is held to.
cv::Mat read_png_with_libpng(const std::filesystem::path& path);

// Encodes CV_8UC1, CV_8UC3 (BGR), CV_8UC4 (BGRA) or CV_16UC1 with libpng. compression 0-9;
// the run-length strategy suits noisy sensor images. Every row uses the Sub filter, as the TUM
// benchmark's frames do: any decoder undoes it faster than the Average and Paeth filters libpng
// would choose. Throws InputError naming the file.
void write_png(const std::filesystem::path& path, const cv::Mat& image, int compression = 1);

}  // namespace slamkit
