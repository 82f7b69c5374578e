#pragma once
// Child processes for the runner: `slamkit run` and `slamkit synth` per entry (a crash stays in
// the child, and entries run side by side), the download script, git.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamkit::regress {

// Runs `program args...` without a shell, stdout and stderr appended to `log`. Returns the exit
// code, 128 + the signal if one ended it, -1 if it could not start.
int run_logged(const std::string& program, const std::vector<std::string>& args,
               const std::filesystem::path& log);

// The program's stdout when it exits with 0 (stderr discarded), else nothing.
std::optional<std::string> capture_output(const std::string& program,
                                          const std::vector<std::string>& args);

}  // namespace slamkit::regress
