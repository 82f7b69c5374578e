#include "eval/plotting.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "core/stopwatch.h"

extern char** environ;

namespace slamkit::eval {
namespace {

// plot.py's exit code when the interpreter cannot import matplotlib (or numpy).
constexpr int kNoMatplotlib = 3;

// Runs `program args...` without a shell; returns its exit code (-1 if it could not start).
int run_program(const std::string& program, const std::vector<std::string>& args) {
  std::vector<std::string> argv_text = {program};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  if (posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string plot_python() {
  const char* env = std::getenv("SLAMKIT_PYTHON");
  return env && *env ? env : "/usr/bin/python3";
}

std::filesystem::path plot_script(const std::string& name = "plot.py") {
  const char* env = std::getenv("SLAMKIT_EVAL_SCRIPTS");
  const std::filesystem::path dir = env && *env ? env : SLAMKIT_EVAL_SCRIPT_DIR;
  return dir / name;
}

}  // namespace

PlotOutcome draw_figures(const nlohmann::json& figures) {
  const std::string python = plot_python();
  Stopwatch watch;
  const int code = run_program(python, {plot_script().string(), figures.dump()});
  PlotOutcome outcome;
  outcome.seconds = watch.lap() / 1000.0;
  outcome.drawn = code == 0;
  outcome.python_missing = code == -1 || code == 127 || code == kNoMatplotlib;
  if (code == -1 || code == 127)
    outcome.problem = "no Python interpreter at '" + python + "' (set SLAMKIT_PYTHON)";
  else if (code == kNoMatplotlib)
    outcome.problem = "'" + python + "' cannot import matplotlib (install python3-matplotlib " +
                      "or set SLAMKIT_PYTHON to an interpreter that has it)";
  else if (code != 0)
    outcome.problem = "the plotting script failed (exit code " + std::to_string(code) + ")";
  return outcome;
}

std::optional<std::filesystem::path> draw_plot(const std::string& script,
                                               const std::vector<std::string>& args,
                                               const std::filesystem::path& png,
                                               const std::string& what) {
  std::vector<std::string> full = {plot_script(script).string()};
  full.insert(full.end(), args.begin(), args.end());
  const int code = run_program(plot_python(), full);
  if (code != 0 || !std::filesystem::exists(png)) {
    std::cerr << "slamkit: note: no " << what << " drawn: " << script << " failed (exit code "
              << code << ")\n";
    return std::nullopt;
  }
  return png;
}

}  // namespace slamkit::eval
