#pragma once
// What identifies a run and its inputs: FNV-1a 64-bit hashes and UTC timestamps. FNV-1a is
// hand-written (a few lines) because SHA-256 would need OpenSSL; it is a published, stable
// hash, fine for identifying files and settings (not for security).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace slamkit {

class Fnv1a64 {
 public:
  void add(const char* data, size_t size);
  std::string hex() const;  // 16 hex digits
  uint64_t value() const { return hash_; }

 private:
  uint64_t hash_ = 0xcbf29ce484222325ull;  // FNV offset basis
};

std::string fnv1a64_hex(std::string_view text);

// The current time as ISO 8601 UTC, to the second ("2026-11-30T08:00:00Z").
std::string utc_now_iso();

}  // namespace slamkit
