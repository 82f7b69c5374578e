#pragma once
#include <string>

namespace slamkit {

// The shortest fixed-notation text that parses back to exactly `value` ("0.8", not
// "0.80000000000000004"; "1305031453.359684" stays as it is).
std::string format_exact(double value);

}  // namespace slamkit
