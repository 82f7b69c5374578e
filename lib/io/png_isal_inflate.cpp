#include "io/png_isal_inflate.h"

#include <isa-l/igzip_lib.h>

#include <cstdint>
#include <limits>
#include <memory>

namespace slamkit {
namespace {

const char* isal_error_text(int code) {
  switch (code) {
    case ISAL_END_INPUT:
      return "the image data ends early";
    case ISAL_OUT_OVERFLOW:
      return "more image data than the header declares";
    case ISAL_INCORRECT_CHECKSUM:
      return "the image data's Adler-32 checksum does not match";
    default:
      return "the image data is not valid deflate data";
  }
}

}  // namespace

bool inflate_with_isal(const unsigned char* in, size_t in_size, unsigned char* out,
                       size_t out_size, std::string& error) {
  constexpr size_t kMax = std::numeric_limits<uint32_t>::max();
  if (in_size > kMax || out_size > kMax) {
    error = "image data of 4 GiB or more";
    return false;
  }
  auto state = std::make_unique<inflate_state>();  // 87 KB: not on a worker thread's stack
  isal_inflate_init(state.get());
  state->crc_flag = ISAL_ZLIB;
  state->next_in = const_cast<unsigned char*>(in);
  state->avail_in = uint32_t(in_size);
  state->next_out = out;
  state->avail_out = uint32_t(out_size);
  const int code = isal_inflate_stateless(state.get());
  if (code != ISAL_DECOMP_OK) {
    error = isal_error_text(code);
    return false;
  }
  if (state->total_out != out_size) {
    error = "less image data than the header declares";
    return false;
  }
  return true;
}

}  // namespace slamkit
