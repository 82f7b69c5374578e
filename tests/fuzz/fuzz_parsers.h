#pragma once
// The inputs slamkit parses, one entry per fuzz target: each calls the function the command
// line calls on such a file. The libFuzzer targets (fuzzer_main.cpp) and the replay of
// tests/fuzz_regressions/ (replay_test.cpp) both go through here, so a finding is replayed by
// the very code that was fuzzed.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slamkit::fuzz {

struct FuzzTarget {
  std::string name;  // the fuzzer is <name>_fuzzer; its findings live in fuzz_regressions/<name>
  // Parses the input file as the CLI would. Success or InputError is a clean outcome; any
  // other exception, a crash or a hang is a finding.
  void (*parse)(const std::filesystem::path& input, const std::filesystem::path& scratch);
};

const std::vector<FuzzTarget>& fuzz_targets();
// Throws std::invalid_argument for a name that is not a target.
const FuzzTarget& fuzz_target(const std::string& name);

// Writes the bytes to a file in a scratch folder of this process and parses it; returns on
// success and on InputError, lets anything else through.
void parse_bytes(const FuzzTarget& target, const uint8_t* data, size_t size);

}  // namespace slamkit::fuzz
