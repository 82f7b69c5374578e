#include "core/error.h"

namespace slamkit {

void throw_input_error(const std::string& path, const std::string& message) {
  throw InputError(path + ": " + message);
}

void throw_input_error(const std::string& path, int line, const std::string& message) {
  throw InputError(path + ":" + std::to_string(line) + ": " + message);
}

}  // namespace slamkit
