#include "eval/regression/run_folder.h"

#include <unistd.h>

#include <atomic>
#include <stdexcept>
#include <string>

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

const char* kAttemptInfix = ".attempt.";

// Renames `path` to a name of this process's own, then deletes it: a rename is atomic, so of
// several processes removing one folder one succeeds and the others see it gone.
void remove_out_of_the_way(const fs::path& path) {
  static std::atomic<int> counter{0};
  const fs::path doomed =
      path.string() + ".removing." + host_and_pid() + "." + std::to_string(counter++);
  std::error_code error;
  fs::rename(path, doomed, error);
  if (error) return;  // gone already, or never there
  fs::remove_all(doomed, error);
  if (error) throw fs::filesystem_error("cannot remove", doomed, error);
}

}  // namespace

std::string host_and_pid() {
  char host[256] = "host";
  gethostname(host, sizeof host - 1);
  return std::string(host) + "." + std::to_string(getpid());
}

fs::path attempt_folder(const fs::path& run_dir) {
  return run_dir.string() + kAttemptInfix + host_and_pid();
}

std::vector<fs::path> attempt_folders(const fs::path& run_dir) {
  std::vector<fs::path> folders;
  std::error_code error;
  const std::string prefix = run_dir.filename().string() + kAttemptInfix;
  for (const fs::directory_entry& e : fs::directory_iterator(run_dir.parent_path(), error))
    if (e.path().filename().string().rfind(prefix, 0) == 0) folders.push_back(e.path());
  return folders;
}

fs::path failed_folder(const fs::path& run_dir) { return run_dir.string() + ".failed"; }

int remove_stale_attempts(const fs::path& run_dir) {
  const std::vector<fs::path> stale = attempt_folders(run_dir);
  for (const fs::path& folder : stale) remove_out_of_the_way(folder);
  return int(stale.size());
}

Publication publish_attempt(const fs::path& attempt, const fs::path& run_dir,
                            const std::function<bool(const fs::path&)>& is_same_run) {
  // Each round either publishes, finds the job published, or clears one folder that another
  // process put there since the last round.
  for (int round = 0; round < 8; ++round) {
    std::error_code error;
    fs::rename(attempt, run_dir, error);
    if (!error) {
      remove_out_of_the_way(failed_folder(run_dir));
      return Publication::kPublished;
    }
    if (!fs::exists(run_dir))
      throw fs::filesystem_error(
          "cannot publish the run (was its attempt folder removed by a later attempt?)", attempt,
          run_dir, error);
    if (is_same_run(run_dir)) {
      remove_out_of_the_way(attempt);
      return Publication::kPublishedByAnother;
    }
    remove_out_of_the_way(run_dir);
  }
  throw std::runtime_error("cannot publish " + attempt.string() + " as " + run_dir.string() +
                           ": other processes keep writing there");
}

void keep_failed_attempt(const fs::path& attempt, const fs::path& run_dir) {
  const fs::path failed = failed_folder(run_dir);
  remove_out_of_the_way(failed);
  std::error_code error;
  fs::rename(attempt, failed, error);  // lost to another failed attempt: the attempt stays
}

}  // namespace slamkit::regress
