// `slamkit settings` prints the defaults as a settings file and, with --markdown, the reference
// table of docs/settings.md: both the library's text, byte for byte.
#include <gtest/gtest.h>

#include "core/settings/settings.h"
#include "settings/settings_reference.h"
#include "settings/settings_yaml.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

TEST(SettingsCommand, PrintsEveryDefaultAsASettingsFile) {
  const test::SlamkitResult result = test::run_slamkit_apart("settings");
  EXPECT_EQ(result.code, 0) << result.err;
  EXPECT_EQ(result.out, settings_yaml_text(Settings{}));
}

TEST(SettingsCommand, MarkdownPrintsTheReference) {
  const test::SlamkitResult result = test::run_slamkit_apart("settings --markdown");
  EXPECT_EQ(result.code, 0) << result.err;
  EXPECT_EQ(result.out, settings_reference_markdown());
}

}  // namespace
}  // namespace slamkit
