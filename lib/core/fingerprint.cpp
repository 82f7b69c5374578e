#include "core/fingerprint.h"

#include <cstdio>
#include <ctime>

namespace slamkit {

void Fnv1a64::add(const char* data, size_t size) {
  for (size_t k = 0; k < size; ++k) {
    hash_ ^= uint8_t(data[k]);
    hash_ *= 0x100000001b3ull;  // FNV prime
  }
}

std::string Fnv1a64::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
  return text;
}

std::string fnv1a64_hex(std::string_view text) {
  Fnv1a64 hash;
  hash.add(text.data(), text.size());
  return hash.hex();
}

std::string utc_now_iso() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace slamkit
