#pragma once
// The values a number read from a file accepts (settings, calibration), and its text for error
// messages.
#include <cmath>
#include <limits>
#include <string>

#include "core/number_format.h"

namespace slamkit {

// The values a number accepts: lo..hi, lo itself excluded when lo_excluded (a scale
// factor must exceed 1). NaN and infinities are outside every range.
struct Range {
  double lo;
  double hi;
  bool lo_excluded = false;
};
inline constexpr double kNoLimit = std::numeric_limits<double>::max();
constexpr Range at_least(double lo) { return {lo, kNoLimit}; }
constexpr Range above(double lo, double hi = kNoLimit) { return {lo, hi, true}; }

inline bool in_range(double value, const Range& range) {
  return std::isfinite(value) && (range.lo_excluded ? value > range.lo : value >= range.lo) &&
         value <= range.hi;
}
// "1..100000", "1 (excluded)..2", "0..inf", "-inf..inf".
inline std::string range_text(const Range& range) {
  return (range.lo == -kNoLimit ? "-inf" : format_exact(range.lo)) +
         (range.lo_excluded ? " (excluded).." : "..") +
         (range.hi == kNoLimit ? "inf" : format_exact(range.hi));
}

}  // namespace slamkit
