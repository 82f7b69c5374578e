// slamkit: one executable, subcommands registered by bin/cmd_*.cpp.
#include <exception>
#include <iostream>
#include <string>

#include "bin/build_info.h"
#include "bin/command.h"
#include "core/error.h"

namespace slamkit::cli {

static std::vector<CommandSetup>& registry() {
  static std::vector<CommandSetup> commands;
  return commands;
}

bool register_command(CommandSetup setup) {
  registry().push_back(std::move(setup));
  return true;
}

const std::vector<CommandSetup>& registered_commands() { return registry(); }

}  // namespace slamkit::cli

int main(int argc, char** argv) {
  CLI::App app{"slamkit: offline RGB-D SLAM reconstruction and evaluation"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("slamkit ") + slamkit::cli::kVersion + " (" +
                                        slamkit::cli::kCommit + ", " + slamkit::cli::kBuildType +
                                        " build)");
  for (const auto& setup : slamkit::cli::registered_commands()) setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const slamkit::cli::ExitCode& e) {
    return e.code;
  } catch (const slamkit::InputError& e) {
    std::cerr << "slamkit: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "slamkit: error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
