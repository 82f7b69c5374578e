#include "eval/plotting.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <iostream>

extern char** environ;

namespace slamkit::eval {

int run_program(const std::string& program, const std::vector<std::string>& args,
                bool silence_output) {
  std::vector<std::string> argv_text = {program};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (silence_output) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid;
  const int spawned = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

PlotPython find_plot_python() {
  const char* env = std::getenv("SLAMKIT_PYTHON");
  const std::string python = env && *env ? env : "/usr/bin/python3";
  PlotPython result;
  const int code = run_program(python, {"-c", "import matplotlib"}, true);
  if (code == 0) {
    result.interpreter = python;
  } else if (code == -1 || code == 127) {
    result.problem = "no Python interpreter at '" + python + "' (set SLAMKIT_PYTHON)";
  } else {
    result.problem = "'" + python + "' cannot import matplotlib (install python3-matplotlib " +
                     "or set SLAMKIT_PYTHON to an interpreter that has it)";
  }
  return result;
}

std::filesystem::path plot_script(const std::string& name) {
  const char* env = std::getenv("SLAMKIT_EVAL_SCRIPTS");
  const std::filesystem::path dir = env && *env ? env : SLAMKIT_EVAL_SCRIPT_DIR;
  return dir / name;
}

std::optional<std::filesystem::path> draw_plot(const std::string& script,
                                               const std::vector<std::string>& args,
                                               const std::filesystem::path& png,
                                               const std::string& what) {
  const PlotPython python = find_plot_python();
  if (!python.interpreter) {
    std::cerr << "slamkit: note: no " << what << " drawn: " << python.problem << "\n";
    return std::nullopt;
  }
  std::vector<std::string> full = {plot_script(script).string()};
  full.insert(full.end(), args.begin(), args.end());
  const int code = run_program(*python.interpreter, full);
  if (code != 0 || !std::filesystem::exists(png)) {
    std::cerr << "slamkit: note: no " << what << " drawn: " << script << " failed (exit code "
              << code << ")\n";
    return std::nullopt;
  }
  return png;
}

}  // namespace slamkit::eval
