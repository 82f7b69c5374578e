#include "png_candidates.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "io/png_file.h"
#include "io/png_source.h"
#include "png_lodepng.h"
#ifdef SLAMKIT_HAVE_LIBDEFLATE
#include <libdeflate.h>
#endif
#ifdef SLAMKIT_HAVE_SPNG
#include <spng.h>
#endif

namespace slamkit::bench {
namespace {

#ifdef SLAMKIT_HAVE_LIBDEFLATE
// libdeflate as lodepng's inflate hook (io/png_lodepng.h), one decompressor per thread.
unsigned inflate_with_libdeflate(unsigned char** out, size_t* out_size, const unsigned char* in,
                                 size_t in_size, const LodePNGDecompressSettings* settings) {
  auto& context = *static_cast<InflateContext*>(const_cast<void*>(settings->custom_context));
  thread_local std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)>
      decompressor(libdeflate_alloc_decompressor(), libdeflate_free_decompressor);
  *out = static_cast<unsigned char*>(std::malloc(context.expected_bytes));
  if (!*out) return 1;
  return libdeflate_zlib_decompress(decompressor.get(), in, in_size, *out, context.expected_bytes,
                                    out_size) != LIBDEFLATE_SUCCESS;
}
#endif

#ifdef SLAMKIT_HAVE_SPNG
// libspng row by row into the image, each row reordered while it is in cache.
cv::Mat decode_with_spng(const std::filesystem::path& path) {
  const PngSource png = load_png_source(path);
  std::unique_ptr<spng_ctx, void (*)(spng_ctx*)> ctx(spng_ctx_new(0), spng_ctx_free);
  spng_set_png_buffer(ctx.get(), png.bytes.data(), png.bytes.size());
  const PngHeader& h = png.header;
  const cv::Mat row_buffer(1, int(h.width),
                           CV_MAKETYPE(h.bit_depth == 16 ? CV_16U : CV_8U, h.channels()));
  cv::Mat image(int(h.height), int(h.width), row_buffer.type());
  if (int error = spng_decode_image(ctx.get(), nullptr, 0, SPNG_FMT_PNG, SPNG_DECODE_PROGRESSIVE))
    throw std::runtime_error(png.name + ": " + spng_strerror(error));
  const size_t row_bytes = image.cols * image.elemSize();
  for (int r = 0; r < image.rows; ++r) {
    const int error = spng_decode_row(ctx.get(), row_buffer.data, row_bytes);
    if (error != 0 && error != SPNG_EOI)
      throw std::runtime_error(png.name + ": " + spng_strerror(error));
    if (h.channels() == 3)
      cv::cvtColor(row_buffer, image.row(r), cv::COLOR_RGB2BGR);
    else if (h.channels() == 4)
      cv::cvtColor(row_buffer, image.row(r), cv::COLOR_RGBA2BGRA);
    else
      row_buffer.copyTo(image.row(r));
  }
  return image;
}
#endif

}  // namespace

std::vector<PngCandidate> png_candidates() {
  std::vector<PngCandidate> all = {
      {"libpng", read_png_with_libpng},
      {"ISA-L inflate, slamkit's unfilter (read_png)", read_png},
      {"lodepng + ISA-L inflate (read_png before)",
       [](const std::filesystem::path& p) {
         return decode_png_with_lodepng(load_png_source(p), inflate_hook_with_isal);
       }},
      {"lodepng, its own inflate",
       [](const std::filesystem::path& p) {
         return decode_png_with_lodepng(load_png_source(p), nullptr);
       }},
      {"OpenCV imread (libpng)",
       [](const std::filesystem::path& p) { return cv::imread(p.string(), cv::IMREAD_UNCHANGED); }},
  };
#ifdef SLAMKIT_HAVE_LIBDEFLATE
  all.push_back({"lodepng + libdeflate", [](const std::filesystem::path& p) {
                   return decode_png_with_lodepng(load_png_source(p), inflate_with_libdeflate);
                 }});
#endif
#ifdef SLAMKIT_HAVE_SPNG
  all.push_back({"libspng", decode_with_spng});
#endif
  return all;
}

}  // namespace slamkit::bench
