// One libFuzzer target; SLAMKIT_FUZZ_TARGET names its entry in fuzz_parsers.cpp.
#include "fuzz_parsers.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const slamkit::fuzz::FuzzTarget& target = slamkit::fuzz::fuzz_target(SLAMKIT_FUZZ_TARGET);
  slamkit::fuzz::parse_bytes(target, data, size);
  return 0;
}
