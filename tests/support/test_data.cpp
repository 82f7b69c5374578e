#include "support/test_data.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>
#include <vector>

namespace slamkit::test {

std::optional<std::filesystem::path> real_data(const std::string& relative) {
  const char* root = std::getenv("SLAMKIT_DATA");
  if (!root || !*root) return std::nullopt;
  const std::filesystem::path path = std::filesystem::path(root) / relative;
  if (!std::filesystem::exists(path)) return std::nullopt;
  return path;
}

bool running_under_ci() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

std::string read_text(const std::filesystem::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

std::filesystem::path write_text(const std::filesystem::path& dir, const std::string& name,
                                 const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

namespace {

// The folders temp_dir handed to the running test.
std::vector<std::filesystem::path>& folders_of_running_test() {
  static std::vector<std::filesystem::path> folders;
  return folders;
}

// Removes a test's folders when it ends without failing, and keeps them when it fails (to be
// looked at) or when SLAMKIT_KEEP_TEST_FILES is set: the suites render thousands of frames,
// and a whole run left 1.5 GB behind.
class RemoveFoldersOfPassedTests : public ::testing::EmptyTestEventListener {
  void OnTestEnd(const ::testing::TestInfo& test) override {
    const char* keep = std::getenv("SLAMKIT_KEEP_TEST_FILES");
    if (!test.result()->Failed() && !(keep && *keep)) {
      for (const auto& folder : folders_of_running_test()) {
        std::error_code ignored;
        std::filesystem::remove_all(folder, ignored);
      }
    }
    folders_of_running_test().clear();
  }
};

// Registered when the test program starts, before gtest_main runs the tests.
const bool kRemovalRegistered = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new RemoveFoldersOfPassedTests);
  return true;
}();

}  // namespace

std::filesystem::path temp_dir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = tag;
  if (info) name += std::string("_") + info->test_suite_name() + "_" + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const auto dir = std::filesystem::temp_directory_path() / "slamkit_tests" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  if (info) folders_of_running_test().push_back(dir);
  return dir;
}

namespace {

// Runs a shell command; returns its exit code (-1 when it did not exit) and its stdout.
int run_command(const std::string& command, std::string* output) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer;
  std::string text;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) text.append(buffer.data(), n);
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int run_slamkit(const std::string& arguments, std::string* output) {
  return run_command(std::string(SLAMKIT_BINARY) + " " + arguments + " 2>&1", output);
}

SlamkitResult run_slamkit_apart(const std::string& arguments) {
  const std::filesystem::path err = temp_dir("stderr") / "stderr.txt";
  SlamkitResult result;
  result.code = run_command(std::string(SLAMKIT_BINARY) + " " + arguments + " 2>" + err.string(),
                            &result.out);
  std::ifstream in(err);
  result.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return result;
}

std::string base64_decode(const std::string& text) {
  static const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  bytes.reserve(text.size() / 4 * 3);
  unsigned bits = 0;
  int bit_count = 0;
  for (const char c : text) {
    const size_t value = alphabet.find(c);
    if (value == std::string::npos) continue;  // '=' padding
    bits = (bits << 6) | static_cast<unsigned>(value);
    bit_count += 6;
    if (bit_count >= 8) {
      bit_count -= 8;
      bytes += static_cast<char>((bits >> bit_count) & 0xFF);
    }
  }
  return bytes;
}

}  // namespace slamkit::test
