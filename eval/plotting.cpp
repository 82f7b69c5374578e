#include "eval/plotting.h"

#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "core/stopwatch.h"
#include "eval/plot_scripts.h"

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

// -B: Python writes no __pycache__ beside the scripts, which would be left behind in an
// installed package's folder when the package is removed (a run as root can write there).
const char* const kNoBytecode = "-B";

std::string plot_python() {
  const char* env = std::getenv("SLAMKIT_PYTHON");
  return env && *env ? env : "/usr/bin/python3";
}

// `script`'s path, else nothing and `problem` says which folders lack it.
std::optional<std::filesystem::path> plot_script(const std::string& script, std::string& problem) {
  const std::vector<std::filesystem::path> dirs = plot_script_dirs();
  if (auto found = find_in(dirs, script)) return found;
  problem = "no " + script + " in";
  for (size_t i = 0; i < dirs.size(); ++i) problem += (i ? " or " : " ") + dirs[i].string();
  problem += " (set SLAMKIT_EVAL_SCRIPTS to the folder of slamkit's plot scripts)";
  return std::nullopt;
}

}  // namespace

nlohmann::json figure_files(const FigureFiles& asked) {
  std::vector<std::string> files;
  for (const std::string& f :
       asked.formats.empty() ? std::vector<std::string>{"png", "svg"} : asked.formats)
    if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
  if (asked.pdf && std::find(files.begin(), files.end(), "pdf") == files.end())
    files.push_back("pdf");
  nlohmann::json fields = {{"formats", files}};
  if (asked.dpi != 0) fields["dpi"] = asked.dpi;
  return fields;
}

PlotOutcome draw_figures(const nlohmann::json& figures) {
  PlotOutcome outcome;
  const std::optional<std::filesystem::path> script = plot_script("plot.py", outcome.problem);
  if (!script) return outcome;
  const std::string python = plot_python();
  Stopwatch watch;
  const int code = run_program(python, {kNoBytecode, script->string(), figures.dump()});
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
  std::string problem;
  const std::optional<std::filesystem::path> path = plot_script(script, problem);
  if (!path) {
    std::cerr << "slamkit: note: no " << what << " drawn: " << problem << "\n";
    return std::nullopt;
  }
  std::vector<std::string> full = {kNoBytecode, path->string()};
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
