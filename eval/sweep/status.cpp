#include "eval/sweep/status.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "eval/regression/run_folder.h"
#include "eval/regression/runner.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;

bool is_one_of(const std::string& state, std::initializer_list<const char*> states) {
  for (const char* s : states)
    if (state == s) return true;
  return false;
}

// run.json's status, "started" for a folder without one.
std::string run_json_status(const fs::path& folder) {
  std::ifstream in(folder / "run.json");
  if (!in) return "started";
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  const nlohmann::json status = j.is_object() ? j.value("status", nlohmann::json()) : nullptr;
  return status.is_string() ? status.get<std::string>() : "started";
}

// Where an unpublished job's run is written or was kept, or "": an attempt that is running,
// else any attempt (one that died), else the last failed attempt.
fs::path unpublished_folder(const fs::path& run_dir) {
  const std::vector<fs::path> attempts = regress::attempt_folders(run_dir);
  for (const fs::path& attempt : attempts)
    if (run_json_status(attempt) == "running") return attempt;
  if (!attempts.empty()) return attempts.front();
  const fs::path failed = regress::failed_folder(run_dir);
  return fs::exists(failed) ? failed : fs::path();
}

}  // namespace

const char* category_name(TaskCategory category) {
  switch (category) {
    case TaskCategory::kDone:
      return "done";
    case TaskCategory::kPending:
      return "pending";
    case TaskCategory::kRunning:
      return "running";
    case TaskCategory::kRequeued:
      return "requeued";
    case TaskCategory::kFailed:
      return "failed";
    case TaskCategory::kMissing:
      return "missing";
  }
  return "?";
}

TaskCategory classify(bool finished, const std::string& folder, const TaskState& slurm_state) {
  const std::string& slurm = slurm_state.state;
  if (finished) return TaskCategory::kDone;
  if (is_one_of(slurm, {"REQUEUED", "REQUEUE_HOLD", "REQUEUE_FED"})) return TaskCategory::kRequeued;
  if (is_one_of(slurm, {"PENDING", "CONFIGURING", "RESV_DEL_HOLD"}))
    return slurm_state.restarts > 0 ? TaskCategory::kRequeued : TaskCategory::kPending;
  if (is_one_of(slurm, {"RUNNING", "COMPLETING", "STAGE_OUT", "SIGNALING", "RESIZING", "SUSPENDED",
                        "STOPPED"}))
    return TaskCategory::kRunning;
  // Every other state has ended (COMPLETED without a finished run folder included).
  if (!slurm.empty()) return TaskCategory::kFailed;
  if (folder == "running") return TaskCategory::kRunning;
  return folder.empty() ? TaskCategory::kMissing : TaskCategory::kFailed;
}

int SweepStatus::count(TaskCategory category) const {
  int n = 0;
  for (const TaskStatus& t : tasks) n += t.category == category;
  return n;
}

std::vector<int> SweepStatus::unfinished() const {
  std::vector<int> indices;
  for (const TaskStatus& t : tasks)
    if (t.category == TaskCategory::kFailed || t.category == TaskCategory::kMissing)
      indices.push_back(t.index);
  return indices;
}

SweepStatus sweep_status(const Plan& plan) {
  SweepStatus status;
  status.submissions = read_submissions(plan.dir);
  const SlurmStates slurm = query_slurm(status.submissions);
  status.slurm_source = slurm.source;
  for (const Job& job : plan.jobs) {
    TaskStatus t;
    t.index = job.index;
    const fs::path run_dir = plan.dir / job.run_folder;
    if (const auto found = slurm.tasks.find(job.index); found != slurm.tasks.end())
      t.slurm = found->second;
    const bool published = fs::exists(run_dir / regress::kEntryMarker);
    const fs::path unpublished = published ? fs::path() : unpublished_folder(run_dir);
    t.category =
        classify(published, unpublished.empty() ? "" : run_json_status(unpublished), t.slurm);
    const size_t underscore = t.slurm.job.find('_');
    const fs::path slurm_log =
        underscore == std::string::npos
            ? fs::path()
            : task_log(plan.dir, t.slurm.job.substr(0, underscore), job.index);
    if (!slurm_log.empty() && fs::exists(slurm_log))
      t.log = slurm_log;
    else if (!unpublished.empty() && fs::exists(unpublished / "run.log"))
      t.log = unpublished / "run.log";
    status.tasks.push_back(t);
  }
  return status;
}

}  // namespace slamkit::sweep
