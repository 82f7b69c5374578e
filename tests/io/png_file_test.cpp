// Our libpng reader and writer against OpenCV's codecs, as an independent reference.
#include "io/png_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

cv::Mat random_image(int type) {
  cv::Mat image(37, 53, type);
  cv::RNG rng(7);
  rng.fill(image, cv::RNG::UNIFORM, 0, type == CV_16UC1 ? 65536 : 256);
  return image;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(PngFile, OursAndOpenCvReadEachOthersFilesExactly) {
  const auto dir = test::temp_dir("png");
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1}) {
    const cv::Mat image = random_image(type);
    write_png(dir / "ours.png", image);
    EXPECT_TRUE(same(cv::imread((dir / "ours.png").string(), cv::IMREAD_UNCHANGED), image))
        << "type " << type;
    cv::imwrite((dir / "opencv.png").string(), image);
    EXPECT_TRUE(same(read_png(dir / "opencv.png"), image)) << "type " << type;
  }
}

TEST(PngFile, RealTumDepthDecodesAsOpenCvDoes) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg1_desk_9frames/depth");
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const cv::Mat ours = read_png(entry.path());
    EXPECT_EQ(ours.type(), CV_16UC1);
    EXPECT_TRUE(same(ours, cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED)));
  }
}

TEST(PngFile, BadFilesAreInputErrorsNamingTheFile) {
  const auto dir = test::temp_dir("png");
  std::ofstream(dir / "text.png") << "not a png";
  std::ofstream(dir / "cut.png", std::ios::binary)
      << std::string("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (const char* name : {"text.png", "cut.png", "missing.png"}) {
    try {
      read_png(dir / name);
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(write_png(dir / "f.png", cv::Mat(4, 4, CV_32FC1)), InputError);
}

TEST(PngFile, HeadersClaimingHugeImagesAreRefusedBeforeAnyPixelMemory) {
  const std::filesystem::path seeds =
      std::filesystem::path(SLAMKIT_SOURCE_DIR) / "tests" / "fuzz" / "seeds" / "png";
  for (const char* name :
       {"rgb_header_claims_100000x100000.png", "depth_header_claims_60000x60000.png"}) {
    try {
      read_png(seeds / name);
      FAIL() << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("images are limited to 16384 pixels a side and 256 MiB"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace slamkit
