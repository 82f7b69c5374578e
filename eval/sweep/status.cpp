#include "eval/sweep/status.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "eval/regression/runner.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;

bool is_one_of(const std::string& state, std::initializer_list<const char*> states) {
  for (const char* s : states)
    if (state == s) return true;
  return false;
}

// run.json's status, "started" for a run folder without one, "" without a run folder.
std::string folder_status(const fs::path& run_dir) {
  if (!fs::exists(run_dir)) return "";
  std::ifstream in(run_dir / "run.json");
  if (!in) return "started";
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  const nlohmann::json status = j.is_object() ? j.value("status", nlohmann::json()) : nullptr;
  return status.is_string() ? status.get<std::string>() : "started";
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
    case TaskCategory::kFailed:
      return "failed";
    case TaskCategory::kMissing:
      return "missing";
  }
  return "?";
}

TaskCategory classify(bool finished, const std::string& folder, const std::string& slurm) {
  if (finished) return TaskCategory::kDone;
  if (is_one_of(slurm, {"PENDING", "REQUEUED", "REQUEUE_HOLD", "REQUEUE_FED", "CONFIGURING",
                        "RESV_DEL_HOLD"}))
    return TaskCategory::kPending;
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
    t.category = classify(fs::exists(run_dir / regress::kEntryMarker), folder_status(run_dir),
                          t.slurm.state);
    const size_t underscore = t.slurm.job.find('_');
    const fs::path slurm_log =
        underscore == std::string::npos
            ? fs::path()
            : task_log(plan.dir, t.slurm.job.substr(0, underscore), job.index);
    if (!slurm_log.empty() && fs::exists(slurm_log))
      t.log = slurm_log;
    else if (fs::exists(run_dir / "run.log"))
      t.log = run_dir / "run.log";
    status.tasks.push_back(t);
  }
  return status;
}

}  // namespace slamkit::sweep
