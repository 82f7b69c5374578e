#include "eval/regression/process.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

extern char** environ;

namespace slamkit::regress {
namespace {

int spawn_and_wait(const std::string& program, const std::vector<std::string>& args,
                   const std::string& out_path, const std::string& err_path) {
  std::vector<std::string> text = {program};
  text.insert(text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : text) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out_path.c_str(), O_WRONLY | O_CREAT | O_APPEND,
                                   0644);
  if (err_path == out_path)
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
  else
    posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY, 0);
  pid_t pid;
  const int spawned = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int run_logged(const std::string& program, const std::vector<std::string>& args,
               const std::filesystem::path& log) {
  return spawn_and_wait(program, args, log.string(), log.string());
}

std::optional<std::string> capture_output(const std::string& program,
                                          const std::vector<std::string>& args) {
  std::string path = (std::filesystem::temp_directory_path() / "slamkit_capture_XXXXXX").string();
  const int fd = mkstemp(path.data());
  if (fd < 0) return std::nullopt;
  close(fd);
  const int code = spawn_and_wait(program, args, path, "/dev/null");
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  std::filesystem::remove(path);
  if (code != 0) return std::nullopt;
  return text.str();
}

}  // namespace slamkit::regress
