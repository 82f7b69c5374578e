#include "core/number_format.h"

#include <charconv>

namespace slamkit {

std::string format_exact(double value) {
  char buffer[400];  // fixed notation of the largest double needs 309 digits
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  return std::string(buffer, end.ptr);
}

}  // namespace slamkit
