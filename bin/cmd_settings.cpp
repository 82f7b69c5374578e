// slamkit settings: every setting with its default, as a settings file (`--settings`) or, with
// --markdown, as the reference docs/settings.md is generated from.
#include <iostream>
#include <memory>

#include "bin/command.h"
#include "settings/settings_reference.h"
#include "settings/settings_yaml.h"

namespace slamkit::cli {
namespace {

const bool kRegistered = register_command([](CLI::App& root) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* cmd =
      root.add_subcommand("settings", "Print every setting with its default, as a settings file");
  cmd->add_flag("--markdown", *markdown,
                "Print the settings reference instead (docs/settings.md: range, source, why)");
  cmd->callback([markdown] {
    std::cout << (*markdown ? settings_reference_markdown() : settings_yaml_text(Settings{}));
  });
});

}  // namespace
}  // namespace slamkit::cli
