#pragma once
// Base64 (RFC 4648, with padding) of raw bytes, to embed binary arrays in the report page; the
// page decodes them with the browser's atob. Written here: none of the stack's libraries
// exposes an encoder (OpenCV's is internal to its persistence code).
#include <cstddef>
#include <string>
#include <vector>

namespace slamkit::eval {

std::string base64_encode(const void* data, size_t bytes);

template <class T>
std::string base64_of(const std::vector<T>& values) {
  return base64_encode(values.data(), values.size() * sizeof(T));
}

}  // namespace slamkit::eval
