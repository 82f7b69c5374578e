#pragma once
// Access to the real TUM data for tests. The folder comes from SLAMKIT_DATA. When it is
// missing, a test needing it fails under CI (CI=true) and is skipped elsewhere, with a
// message saying what to set.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

namespace slamkit::test {

// $SLAMKIT_DATA/<relative> if that exists.
std::optional<std::filesystem::path> real_data(const std::string& relative);

bool running_under_ci();

// The whole text of a file ("" when it cannot be read).
std::string read_text(const std::filesystem::path& file);
// Writes `text` to dir/name and returns that path.
std::filesystem::path write_text(const std::filesystem::path& dir, const std::string& name,
                                 const std::string& text);

// The bytes of base64 text (RFC 4648; padding and other characters skipped): screenshots from
// the browser, arrays embedded in report pages.
std::string base64_decode(const std::string& text);

// A fresh empty folder under the system temp dir, unique per test; removed when the test
// passes, kept when it fails or when SLAMKIT_KEEP_TEST_FILES is set.
std::filesystem::path temp_dir(const std::string& tag);

// Runs the slamkit executable with the given arguments; returns its exit code and puts
// stdout+stderr into `output`.
int run_slamkit(const std::string& arguments, std::string* output = nullptr);

// Runs the slamkit executable with stdout and stderr kept apart.
struct SlamkitResult {
  int code = -1;
  std::string out;
  std::string err;
};
SlamkitResult run_slamkit_apart(const std::string& arguments);

}  // namespace slamkit::test

// Declares `var` as the real-data path, or fails (CI) / skips (elsewhere) the test.
#define SLAMKIT_REQUIRE_DATA(var, relative)                                         \
  const auto var##_found = ::slamkit::test::real_data(relative);                    \
  if (!var##_found) {                                                               \
    const std::string why = std::string("real data '") + (relative) +               \
                            "' not found: set SLAMKIT_DATA to the datasets folder"; \
    if (::slamkit::test::running_under_ci()) FAIL() << why;                         \
    GTEST_SKIP() << why;                                                            \
  }                                                                                 \
  const std::filesystem::path var = *var##_found
