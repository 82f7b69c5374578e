// slamkit: one executable, subcommands registered by bin/cmd_*.cpp.
#include <malloc.h>

#include <cstdlib>
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
  // glibc gives threads that allocate at the same time arenas of their own (up to 8 a core) and
  // keeps what is freed in each; two arenas serve the pipeline's threads as fast and hold less
  // (desk 600's peak 266 -> 244 MB; docs/experiments.md). MALLOC_ARENA_MAX, if set, decides.
  if (!std::getenv("MALLOC_ARENA_MAX")) mallopt(M_ARENA_MAX, 2);
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
