#include "loop/binary_descriptor.h"

#include <cstring>

namespace slamkit {
namespace {

// Each byte value spread into 8 one-byte lanes (bit b -> lane b), so that adding the spreads of
// up to 255 descriptors counts 8 bits at once without carries between lanes (SWAR; no library
// counts bits column-wise). A quarter of the vocabulary's training time went to the bit loop.
struct ByteSpread {
  uint64_t lanes[256];
  ByteSpread() {
    for (int v = 0; v < 256; ++v) {
      lanes[v] = 0;
      for (int bit = 0; bit < 8; ++bit) lanes[v] |= uint64_t((v >> bit) & 1) << (8 * bit);
    }
  }
};

}  // namespace

Descriptor majority_descriptor(const std::vector<const uint8_t*>& members) {
  static const ByteSpread spread;
  std::array<int, kDescriptorBytes * 8> set_count{};
  std::array<uint64_t, kDescriptorBytes> partial{};
  const auto flush = [&] {
    for (int byte = 0; byte < kDescriptorBytes; ++byte) {
      uint8_t lane[8];
      std::memcpy(lane, &partial[byte], 8);  // lane b of the little-endian word: bit b
      for (int bit = 0; bit < 8; ++bit) set_count[byte * 8 + bit] += lane[bit];
    }
    partial.fill(0);
  };
  size_t pending = 0;
  for (const uint8_t* d : members) {
    for (int byte = 0; byte < kDescriptorBytes; ++byte) partial[byte] += spread.lanes[d[byte]];
    if (++pending == 255) flush(), pending = 0;
  }
  flush();
  Descriptor centre{};
  for (int byte = 0; byte < kDescriptorBytes; ++byte)
    for (int bit = 0; bit < 8; ++bit)
      if (2 * set_count[byte * 8 + bit] > int(members.size())) centre[byte] |= uint8_t(1u << bit);
  return centre;
}

}  // namespace slamkit
