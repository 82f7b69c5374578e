#pragma once
// A run folder is published whole, by one attempt. Each attempt writes into a folder of its own
// beside the run folder, "<run>.attempt.<host>.<pid>", and publishes it by renaming it to the run
// folder. A rename onto a folder that holds files fails, so when two attempts of one job finish
// (a task requeued off a node that was not dead after all, a job cancelled and resubmitted while
// it ran) exactly one publishes and the other discards its copy. An attempt that dies leaves only
// its own attempt folder, never a half-written run folder; the next attempt of the job removes it.
// A failed attempt is kept as "<run>.failed" for its log until the job succeeds.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace slamkit::regress {

// "<host>.<pid>": no two live processes of a cluster share it.
std::string host_and_pid();

// This process's attempt folder for `run_dir` (not created).
std::filesystem::path attempt_folder(const std::filesystem::path& run_dir);

// The attempt folders of `run_dir` there are now, this process's own included.
std::vector<std::filesystem::path> attempt_folders(const std::filesystem::path& run_dir);

// Where the last failed attempt of `run_dir` is kept.
std::filesystem::path failed_folder(const std::filesystem::path& run_dir);

// Removes the attempt folders earlier attempts of `run_dir` left (one with this process's name
// too: a dead process on this host may have had its pid); how many there were. Called before
// this attempt creates its own. Each is renamed out of the way before it is deleted, so a
// writer still alive on a lost node can only fail, never write into a later attempt's folder.
int remove_stale_attempts(const std::filesystem::path& run_dir);

enum class Publication { kPublished, kPublishedByAnother };

// Renames `attempt` to `run_dir`. A folder already at `run_dir` that `is_same_run` accepts was
// published by another attempt: `attempt` is removed and kPublishedByAnother returned. Any other
// folder there (an older run of other settings, a folder cut short by an earlier slamkit) is
// moved away and removed first. On success the job's failed folder goes too.
Publication publish_attempt(const std::filesystem::path& attempt,
                            const std::filesystem::path& run_dir,
                            const std::function<bool(const std::filesystem::path&)>& is_same_run);

// Keeps a failed `attempt` as failed_folder(run_dir), replacing an earlier one.
void keep_failed_attempt(const std::filesystem::path& attempt,
                         const std::filesystem::path& run_dir);

}  // namespace slamkit::regress
