#pragma once
// Checks of an output path (--out, --plot) made before a command writes anything, so that a bad
// one is refused in slamkit's words (exit 2) rather than with the file system's message, and so
// that no command writes among the files of the sequence it reads.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace slamkit::cli {

// InputError "OPTION PATH: ..." when `folder` exists and is not a folder, or when one of its
// parents is a file.
void check_output_folder(const std::string& option, const std::filesystem::path& folder);

// The same for a file to write (vocab train --out FILE): InputError when `file` is a folder or
// one of its parents is a file.
void check_output_file(const std::string& option, const std::filesystem::path& file);

// InputError naming the option and both paths when `out` is one of the `sequences` folders or
// inside one (symlinks and `..` resolved), unless `allowed`.
void check_output_outside_sequences(const std::string& option, const std::filesystem::path& out,
                                    const std::vector<std::string>& sequences, bool allowed);

// Adds --allow-out-in-sequence to a command that reads sequences and writes --out.
void add_allow_out_in_sequence_flag(CLI::App* command, bool& allowed);

}  // namespace slamkit::cli
