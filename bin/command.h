#pragma once
// Subcommands register themselves: each bin/cmd_*.cpp defines one static registration, so a
// new subcommand is one new file and main.cpp never changes.
#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace slamkit::cli {

// Thrown by a command to end the program with a given exit code (e.g. 1 for a failed
// regression check); errors in the input are InputError and exit with 2.
struct ExitCode {
  int code;
};

// Adds a subcommand (with its options and callback) to the root app.
using CommandSetup = std::function<void(CLI::App& root)>;

// Returns true so it can initialise a static: `static const bool kRegistered = ...;`.
bool register_command(CommandSetup setup);
const std::vector<CommandSetup>& registered_commands();

}  // namespace slamkit::cli
