// Every crash, hang or out-of-memory input a fuzz target ever found (tests/fuzz_regressions/
// <target>/) is parsed again on every test run, through the same entry as the fuzzer and under
// limits like the fuzzer's: each must now succeed or be refused with an InputError.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>

#include "fuzz_parsers.h"

// Under ASan, whose shadow memory needs more address space than the limit below, an allocation
// over 1 GiB is its report instead.
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=1024"; }

namespace slamkit::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(SLAMKIT_SOURCE_DIR) / "tests" / "fuzz_regressions";
constexpr unsigned kSecondsPerInput = 10;  // scripts/fuzz.sh's -timeout
constexpr rlim_t kAddressSpace = rlim_t(1) << 30;  // the largest valid input, a 256 MiB image, fits

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool under_address_sanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#endif
#endif
  return false;
}

// Parses the file in a child process with a time and memory limit; "" when the outcome was
// clean, else what went wrong.
std::string replay(const FuzzTarget& target, const fs::path& file) {
  const std::string bytes = read_bytes(file);
  const pid_t child = fork();
  if (child < 0) return "cannot fork";
  if (child == 0) {
    alarm(kSecondsPerInput);
    if (!under_address_sanitizer()) {
      const rlimit limit{kAddressSpace, kAddressSpace};
      setrlimit(RLIMIT_AS, &limit);
    }
    try {
      parse_bytes(target, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", file.c_str(), e.what());
      _exit(1);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  if (WIFEXITED(status)) return "an exception other than InputError (its message above)";
  if (WTERMSIG(status) == SIGALRM)
    return "took over " + std::to_string(kSecondsPerInput) + " s (a hang)";
  return std::string("killed by signal ") + strsignal(WTERMSIG(status));
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
  int replayed = 0;
  for (const auto& entry :
       fs::directory_iterator(kRegressions / GetParam().name, fs::directory_options::none, ignored)) {
    if (!entry.is_regular_file()) continue;
    const std::string problem = replay(GetParam(), entry.path());
    EXPECT_EQ(problem, "") << entry.path();
    ++replayed;
  }
  std::printf("%s: %d stored finding(s) replayed\n", GetParam().name.c_str(), replayed);
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzReplay, ::testing::ValuesIn(fuzz_targets()),
                         [](const auto& test_param) { return test_param.param.name; });

}  // namespace
}  // namespace slamkit::fuzz
