// Every crash or hang a fuzz target ever found (tests/fuzz_regressions/<target>/) is parsed
// again on every test run, through the same entry as the fuzzer: each must now succeed or be
// refused with an InputError.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "fuzz_parsers.h"

namespace slamkit::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(SLAMKIT_SOURCE_DIR) / "tests" / "fuzz_regressions";

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST(FuzzRegressions, EveryFolderNamesATarget) {
  ASSERT_TRUE(fs::is_directory(kRegressions));
  for (const auto& entry : fs::directory_iterator(kRegressions)) {
    if (!entry.is_directory()) continue;
    EXPECT_NO_THROW(fuzz_target(entry.path().filename().string())) << entry.path();
  }
}

class FuzzReplay : public ::testing::TestWithParam<FuzzTarget> {};

}  // namespace

// Test names and messages show the target's name.
void PrintTo(const FuzzTarget& target, std::ostream* out) { *out << target.name; }

namespace {

TEST_P(FuzzReplay, EveryStoredFindingIsParsedOrRefusedCleanly) {
  std::error_code ignored;  // a target without findings has no folder
  const fs::path folder = kRegressions / GetParam().name;
  int replayed = 0;
  for (const auto& entry : fs::directory_iterator(folder, fs::directory_options::none, ignored)) {
    if (!entry.is_regular_file()) continue;
    const std::string bytes = read_bytes(entry.path());
    try {
      parse_bytes(GetParam(), reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
    ++replayed;
  }
  std::printf("%s: %d stored finding(s) replayed\n", GetParam().name.c_str(), replayed);
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay, ::testing::ValuesIn(fuzz_targets()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace slamkit::fuzz
