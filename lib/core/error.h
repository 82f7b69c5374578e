#pragma once
// Errors raised at the I/O boundary. The message always names the file (and the line when
// one is at fault); the CLI prints it as one line and exits with code 2.
#include <stdexcept>
#include <string>

namespace slamkit {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "path: message" or "path:line: message" (line numbers count from 1).
[[noreturn]] void throw_input_error(const std::string& path, const std::string& message);
[[noreturn]] void throw_input_error(const std::string& path, int line, const std::string& message);

}  // namespace slamkit
