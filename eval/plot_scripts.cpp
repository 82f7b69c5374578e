#include "eval/plot_scripts.h"

#include <cstdlib>
#include <system_error>

namespace slamkit::eval {

std::vector<std::filesystem::path> plot_script_dirs(const char* env_dir,
                                                    const std::filesystem::path& executable) {
  if (env_dir && *env_dir) return {env_dir};
  std::vector<std::filesystem::path> dirs;
  if (!executable.empty())
    dirs.push_back((executable.parent_path() / SLAMKIT_INSTALLED_EVAL_SCRIPTS).lexically_normal());
  dirs.push_back(SLAMKIT_EVAL_SCRIPT_DIR);
  return dirs;
}

std::vector<std::filesystem::path> plot_script_dirs() {
  // The running binary with symlinks resolved: a link to it elsewhere (~/bin/slamkit) still
  // finds the scripts of its install.
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  return plot_script_dirs(std::getenv("SLAMKIT_EVAL_SCRIPTS"), error ? "" : executable);
}

std::optional<std::filesystem::path> find_in(const std::vector<std::filesystem::path>& dirs,
                                             const std::string& script) {
  for (const std::filesystem::path& dir : dirs) {
    std::error_code error;
    if (std::filesystem::is_regular_file(dir / script, error)) return dir / script;
  }
  return std::nullopt;
}

}  // namespace slamkit::eval
