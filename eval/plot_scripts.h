#pragma once
// Where the plot scripts (eval/*.py) are. An installed slamkit finds them beside itself, so the
// install can move (cmake --install --prefix, the .deb); the binary of a build tree finds them
// in the source folder, so an edit to a script counts at once.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamkit::eval {

// The folders to look in, in order. `env_dir` ($SLAMKIT_EVAL_SCRIPTS; null or empty when
// unset) is the only one when given. Else the install layout's folder relative to the folder
// of `executable` (skipped when that is empty), then the source folder of eval/. The installed
// folder goes first: where the binary was built the source folder exists too, and an installed
// binary must not run the scripts of whatever the checkout holds by then.
std::vector<std::filesystem::path> plot_script_dirs(const char* env_dir,
                                                    const std::filesystem::path& executable);

// The same for this process: $SLAMKIT_EVAL_SCRIPTS and the running executable.
std::vector<std::filesystem::path> plot_script_dirs();

// `script` in the first of `dirs` that holds it, else nothing.
std::optional<std::filesystem::path> find_in(const std::vector<std::filesystem::path>& dirs,
                                             const std::string& script);

}  // namespace slamkit::eval
