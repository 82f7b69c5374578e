// Our PNG reader (ISA-L's inflate and our unfilter, libpng for the rest) and writer against libpng alone and
// OpenCV's codecs, as independent references.
#include "io/png_file.h"

#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <cstdio>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

cv::Mat random_image(int type) {
  cv::Mat image(37, 53, type);
  cv::RNG rng(7);
  rng.fill(image, cv::RNG::UNIFORM, 0, CV_MAT_DEPTH(type) == CV_16U ? 65536 : 256);
  return image;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Offset of the first chunk of `type` (its length field) in a PNG's bytes.
size_t find_chunk(const std::string& png, const std::string& type) {
  const size_t at = png.find(type);
  EXPECT_NE(at, std::string::npos) << type;
  return at - 4;
}

// Recomputes the CRC of the chunk at `at`, so that a test's edit reaches the decoder.
void fix_crc(std::string& png, size_t at) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(png.data());
  const uint32_t length =
      uint32_t(bytes[at]) << 24 | bytes[at + 1] << 16 | bytes[at + 2] << 8 | bytes[at + 3];
  const uLong crc = crc32(0, bytes + at + 4, length + 4);
  for (int k = 0; k < 4; ++k) png[at + 8 + length + size_t(k)] = char(crc >> (24 - 8 * k));
}

void expect_input_error_naming(const fs::path& file) {
  for (const auto reader : {read_png, read_png_with_libpng}) {
    try {
      reader(file);
      ADD_FAILURE() << file << " was decoded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos)
          << e.what();
    }
  }
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

// Writes `image` (CV_8UC1/3/4 or CV_16UC1/3, samples as stored: no BGR swap) with libpng,
// every row filtered by `filter` (PNG_FILTER_NONE ... PNG_FILTER_PAETH): files that read_png
// must undo as libpng does, written independently of our writer.
void write_with_libpng_filter(const fs::path& path, const cv::Mat& image, int filter) {
  std::FILE* file = std::fopen(path.string().c_str(), "wb");
  ASSERT_NE(file, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, file);
  const int colour = image.channels() == 1   ? PNG_COLOR_TYPE_GRAY
                     : image.channels() == 3 ? PNG_COLOR_TYPE_RGB
                                             : PNG_COLOR_TYPE_RGB_ALPHA;
  png_set_IHDR(png, info, png_uint_32(image.cols), png_uint_32(image.rows),
               image.depth() == CV_16U ? 16 : 8, colour, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, filter);
  png_write_info(png, info);
  if (image.depth() == CV_16U) png_set_swap(png);
  for (int r = 0; r < image.rows; ++r) png_write_row(png, image.ptr<png_byte>(r));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(file);
}

// `png` with its image data replaced by `scanlines` (filter bytes and rows), deflated into
// one IDAT chunk: for damage that passes every CRC and the deflate checks.
std::string with_scanlines(const std::string& png, const std::vector<unsigned char>& scanlines) {
  uLongf size = compressBound(scanlines.size());
  std::string deflated(size, '\0');
  EXPECT_EQ(compress(reinterpret_cast<Bytef*>(deflated.data()), &size, scanlines.data(),
                     scanlines.size()),
            Z_OK);
  deflated.resize(size);
  const size_t idat = find_chunk(png, "IDAT"), iend = find_chunk(png, "IEND");
  std::string chunk(4, '\0');
  for (int k = 0; k < 4; ++k) chunk[size_t(k)] = char(size >> (24 - 8 * k));
  chunk += "IDAT" + deflated + std::string(4, '\0');
  std::string result = png.substr(0, idat) + chunk + png.substr(iend);
  fix_crc(result, idat);
  return result;
}

// The inflated scanlines of a file we wrote (one filter byte and the row's bytes each).
std::vector<unsigned char> scanlines_of(const std::string& png, const cv::Mat& image) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(png.data());
  std::string deflated;
  for (size_t at = 8; at + 12 <= png.size();) {
    const size_t length = size_t(bytes[at]) << 24 | size_t(bytes[at + 1]) << 16 |
                          size_t(bytes[at + 2]) << 8 | bytes[at + 3];
    if (png.compare(at + 4, 4, "IDAT") == 0) deflated += png.substr(at + 8, length);
    at += 12 + length;
  }
  std::vector<unsigned char> raw((1 + size_t(image.cols) * image.elemSize()) * size_t(image.rows));
  uLongf raw_size = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &raw_size,
                       reinterpret_cast<const Bytef*>(deflated.data()), deflated.size()),
            Z_OK);
  EXPECT_EQ(raw_size, raw.size());
  return raw;
}

// Each row's filter byte (0 None ... 4 Paeth) of a PNG file's bytes.
std::vector<int> row_filters(const std::string& png, const cv::Mat& image) {
  const std::vector<unsigned char> raw = scanlines_of(png, image);
  const size_t scanline = raw.size() / size_t(image.rows);
  std::vector<int> filters;
  for (size_t r = 0; r < size_t(image.rows); ++r) filters.push_back(raw[r * scanline]);
  return filters;
}

TEST(PngFile, WrittenRowsAllUseTheSubFilterAsTumFramesDo) {
  // Sub on every row, as the TUM benchmark's own frames are written: decoders undo it fastest
  // (libpng's adaptive choice, mostly Average and Paeth on rendered frames, took lodepng 5.8 ms
  // a synthetic colour frame against 2.6 for a TUM one).
  const auto dir = test::temp_dir("png");
  for (int type : {CV_8UC1, CV_8UC3, CV_16UC1}) {
    const cv::Mat image = random_image(type);
    write_png(dir / "sub.png", image);
    EXPECT_EQ(row_filters(file_bytes(dir / "sub.png"), image),
              std::vector<int>(size_t(image.rows), 1))
        << "type " << type;
  }
}

TEST(PngFile, EveryLayoutDecodesAsLibpngDoes) {
  const auto dir = test::temp_dir("png");
  // The fast decoder's layouts, 16-bit colour included.
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4}) {
    const cv::Mat image = random_image(type);
    cv::imwrite((dir / "image.png").string(), image);
    EXPECT_TRUE(same(read_png(dir / "image.png"), image)) << "type " << type;
    EXPECT_TRUE(same(read_png_with_libpng(dir / "image.png"), image)) << "type " << type;
  }
  // 1-bit grey goes to libpng, which expands it to 8 bits (0 and 255).
  cv::Mat bilevel = random_image(CV_8UC1) > 127;
  cv::imwrite((dir / "bilevel.png").string(), bilevel, {cv::IMWRITE_PNG_BILEVEL, 1});
  EXPECT_TRUE(same(read_png(dir / "bilevel.png"), bilevel));
}

TEST(PngFile, EachRowFilterIsUndoneAsLibpngDoes) {
  // read_png undoes the five filters itself (io/png_unfilter.h); libpng is the reference, and
  // the image written is the truth. Every pixel size the unfilter knows: 1, 2, 3, 4, 6 bytes.
  const auto dir = test::temp_dir("png");
  const std::vector<std::pair<int, int>> filters = {{PNG_FILTER_NONE, 0}, {PNG_FILTER_SUB, 1},
                                                    {PNG_FILTER_UP, 2}, {PNG_FILTER_AVG, 3},
                                                    {PNG_FILTER_PAETH, 4}};
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3}) {
    const cv::Mat image = random_image(type);
    for (const auto& [filter, code] : filters) {
      const fs::path file = dir / "filtered.png";
      write_with_libpng_filter(file, image, filter);
      const std::vector<int> used = row_filters(file_bytes(file), image);
      EXPECT_EQ(std::count(used.begin() + 1, used.end(), code), image.rows - 1)
          << "rows after the first use filter " << code;
      cv::Mat expected = image;  // written as RGB(A); read as BGR(A)
      if (image.channels() == 3) cv::cvtColor(image, expected, cv::COLOR_RGB2BGR);
      if (image.channels() == 4) cv::cvtColor(image, expected, cv::COLOR_RGBA2BGRA);
      EXPECT_TRUE(same(read_png(file), expected)) << "type " << type << ", filter " << code;
      EXPECT_TRUE(same(read_png_with_libpng(file), expected)) << "type " << type << ", filter " << code;
    }
  }
}

TEST(PngFile, UnknownFilterTypesAndShortImageDataAreInputErrors) {
  const auto dir = test::temp_dir("png");
  const cv::Mat image = random_image(CV_8UC3);
  write_png(dir / "good.png", image);
  const std::string good = file_bytes(dir / "good.png");
  std::vector<unsigned char> scanlines = scanlines_of(good, image);
  const size_t scanline = scanlines.size() / size_t(image.rows);

  std::vector<unsigned char> bad_filter = scanlines;
  bad_filter[5 * scanline] = 7;  // row 5: no such filter
  write_bytes(dir / "filter.png", with_scanlines(good, bad_filter));
  std::vector<unsigned char> short_data(scanlines.begin(), scanlines.end() - long(scanline));
  write_bytes(dir / "rows.png", with_scanlines(good, short_data));  // a row missing, valid zlib
  write_bytes(dir / "same.png", with_scanlines(good, scanlines));   // the helper itself is sound
  EXPECT_TRUE(same(read_png(dir / "same.png"), image));
  for (const char* name : {"filter.png", "rows.png"}) expect_input_error_naming(dir / name);
  try {
    read_png(dir / "filter.png");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown filter type 7 in row 5"), std::string::npos)
        << e.what();
  }
  try {
    read_png(dir / "rows.png");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("less image data than the header declares"),
              std::string::npos)
        << e.what();
  }
}

TEST(PngFile, EverySharedRealFrameDecodesAsLibpngDoes) {
  SLAMKIT_REQUIRE_DATA(root, ".");
  size_t colour = 0, depth = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".png") continue;
    const cv::Mat ours = read_png(entry.path());
    EXPECT_TRUE(same(ours, read_png_with_libpng(entry.path()))) << entry.path();
    colour += ours.type() == CV_8UC3;
    depth += ours.type() == CV_16UC1;
  }
  // fr2/desk's 50 pairs and fr1/desk's 9 at least; a full sequence has more.
  EXPECT_GE(colour, 59u);
  EXPECT_GE(depth, 59u);
}

TEST(PngFile, RealTumDepthDecodesAsOpenCvDoes) {
  SLAMKIT_REQUIRE_DATA(folder, "rgbd_dataset_freiburg1_desk_9frames/depth");
  for (const auto& entry : fs::directory_iterator(folder)) {
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
  for (const char* name : {"text.png", "cut.png", "missing.png"})
    expect_input_error_naming(dir / name);
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

TEST(PngFile, DamagedImageDataIsAnInputErrorNamingTheFile) {
  const auto dir = test::temp_dir("png");
  write_png(dir / "good.png", random_image(CV_16UC1));
  const std::string good = file_bytes(dir / "good.png");
  const size_t idat = find_chunk(good, "IDAT");

  std::string flipped = good;  // a bit flipped in the image data: the chunk's CRC fails
  flipped[idat + 20] = char(flipped[idat + 20] ^ 1);
  write_bytes(dir / "crc.png", flipped);
  fix_crc(flipped, idat);  // the CRC made to fit: the deflate data or Adler-32 fails
  write_bytes(dir / "deflate.png", flipped);
  write_bytes(dir / "short.png", good.substr(0, idat + 30));  // cut inside the image data
  for (const char* name : {"crc.png", "deflate.png", "short.png"})
    expect_input_error_naming(dir / name);
}

TEST(PngFile, HugeDeclaredSizeIsRefusedBeforeDecoding) {
  const auto dir = test::temp_dir("png");
  write_png(dir / "small.png", random_image(CV_8UC3));
  std::string png = file_bytes(dir / "small.png");
  const size_t ihdr = find_chunk(png, "IHDR");
  // 200000 x 200000 RGB: 120 GB, from a file of a few kilobytes.
  for (size_t field : {ihdr + 8, ihdr + 12})
    png.replace(field, 4, std::string("\0\x03\x0d\x40", 4));
  fix_crc(png, ihdr);
  write_bytes(dir / "huge.png", png);
  expect_input_error_naming(dir / "huge.png");
  try {
    read_png(dir / "huge.png");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("200000 x 200000"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamkit
