#include "io/png_libpng.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "core/error.h"
#include "io/png_file.h"

namespace slamkit {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// libpng reports errors by longjmp; this keeps its message for the exception thrown after.
void on_png_error(png_structp png, png_const_charp message) {
  *static_cast<std::string*>(png_get_error_ptr(png)) = message;
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

// libpng reads the file's bytes from memory, already loaded and checked by load_png_source.
struct MemoryReader {
  const std::vector<unsigned char>& bytes;
  size_t at = 0;
};
void read_from_memory(png_structp png, png_bytep out, png_size_t size) {
  auto* reader = static_cast<MemoryReader*>(png_get_io_ptr(png));
  if (size > reader->bytes.size() - reader->at) png_error(png, "file ends early");
  std::memcpy(out, reader->bytes.data() + reader->at, size);
  reader->at += size;
}

}  // namespace

cv::Mat decode_png_with_libpng(const PngSource& source) {
  std::string error;
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) throw_input_error(source.name, "cannot decode image (out of memory)");
  // Ancillary chunks are skipped unread: libpng takes (and clears) the memory a text chunk's
  // length field claims before reading it, 1.7 GB for a 74-byte file. Nothing of them is used;
  // tRNS (transparency) would turn a grey image into grey+alpha.
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, nullptr, -1);
  static const png_byte kTransparency[] = "tRNS";
  png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, kTransparency, 1);
  MemoryReader reader{source.bytes};
  cv::Mat image;
  std::vector<png_bytep> rows;
  if (setjmp(png_jmpbuf(png))) {  // libpng jumps back here on a decoding error
    png_destroy_read_struct(&png, &info, nullptr);
    throw_input_error(source.name, "cannot decode image: " + error);
  }
  png_set_read_fn(png, &reader, read_from_memory);
  png_read_info(png, info);
  const int colour = png_get_color_type(png, info);
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (png_get_bit_depth(png, info) < 8) png_set_packing(png), png_set_expand(png);
  if (colour == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_strip_alpha(png);
  if (colour & PNG_COLOR_MASK_COLOR || colour == PNG_COLOR_TYPE_PALETTE) png_set_bgr(png);
  png_set_swap(png);  // 16-bit samples are big-endian in the file
  png_read_update_info(png, info);

  const int depth = png_get_bit_depth(png, info) == 16 ? CV_16U : CV_8U;
  const int channels = png_get_channels(png, info);
  image.create(int(png_get_image_height(png, info)), int(png_get_image_width(png, info)),
               CV_MAKETYPE(depth, channels));
  rows.resize(size_t(image.rows));
  for (int r = 0; r < image.rows; ++r) rows[size_t(r)] = image.ptr<png_byte>(r);
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return image;
}

void write_png(const std::filesystem::path& path, const cv::Mat& image, int compression) {
  const std::string name = path.string();
  int colour = 0;
  switch (image.type()) {
    case CV_8UC1:
    case CV_16UC1:
      colour = PNG_COLOR_TYPE_GRAY;
      break;
    case CV_8UC3:
      colour = PNG_COLOR_TYPE_RGB;
      break;
    case CV_8UC4:
      colour = PNG_COLOR_TYPE_RGB_ALPHA;
      break;
    default:
      throw_input_error(name, "cannot write this image type as PNG");
  }
  File file(std::fopen(name.c_str(), "wb"));
  if (!file) throw_input_error(name, "cannot write file");
  std::string error;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) throw_input_error(name, "cannot encode image (out of memory)");
  std::vector<png_bytep> rows(size_t(image.rows));
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw_input_error(name, "cannot write PNG: " + error);
  }
  png_init_io(png, file.get());
  png_set_compression_level(png, compression);
  png_set_compression_strategy(png, Z_RLE);
  // Sub on every row (png_file.h): synthetic desk 600's `run` took 10 % less CPU.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(png, info, png_uint_32(image.cols), png_uint_32(image.rows),
               image.depth() == CV_16U ? 16 : 8, colour, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  if (image.channels() > 1) png_set_bgr(png);
  if (image.depth() == CV_16U) png_set_swap(png);
  for (int r = 0; r < image.rows; ++r)
    rows[size_t(r)] = const_cast<png_bytep>(image.ptr<png_byte>(r));
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fflush(file.get()) != 0) throw_input_error(name, "write failed");
}

}  // namespace slamkit
