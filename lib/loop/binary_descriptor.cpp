#include "loop/binary_descriptor.h"

namespace slamkit {

Descriptor majority_descriptor(const std::vector<const uint8_t*>& members) {
  std::array<int, kDescriptorBytes * 8> set_count{};
  for (const uint8_t* d : members)
    for (int byte = 0; byte < kDescriptorBytes; ++byte)
      for (int bit = 0; bit < 8; ++bit) set_count[byte * 8 + bit] += (d[byte] >> bit) & 1;
  Descriptor centre{};
  for (int byte = 0; byte < kDescriptorBytes; ++byte)
    for (int bit = 0; bit < 8; ++bit)
      if (2 * set_count[byte * 8 + bit] > int(members.size())) centre[byte] |= uint8_t(1u << bit);
  return centre;
}

}  // namespace slamkit
