#pragma once
// Where each job of a sweep stands, from its run folder and, for a sweep handed to Slurm, from
// Slurm's word on its array task: done (the run folder's finished marker), pending or running
// (Slurm, or run.json for a run on this machine), failed (it ended without a finished run:
// its run failed, it was cancelled, ran out of time or memory, its node died) or missing (no
// trace of it).
#include <filesystem>
#include <string>
#include <vector>

#include "eval/sweep/plan.h"
#include "eval/sweep/slurm.h"

namespace slamkit::sweep {

enum class TaskCategory { kDone, kPending, kRunning, kFailed, kMissing };
const char* category_name(TaskCategory category);  // "done", "pending", ...

// The category from what the run folder holds and what Slurm says (empty: nothing).
// folder_status: "" (no run folder), run.json's status, or "started" (a folder without it).
TaskCategory classify(bool finished, const std::string& folder_status,
                      const std::string& slurm_state);

struct TaskStatus {
  int index = 0;
  TaskCategory category = TaskCategory::kMissing;
  TaskState slurm;            // empty when Slurm has no word on it
  std::filesystem::path log;  // Slurm's log of the task, else the run's, else empty
};

struct SweepStatus {
  std::vector<TaskStatus> tasks;  // one per job, in index order
  std::vector<Submission> submissions;
  std::string slurm_source;  // which commands answered; empty without submissions

  int count(TaskCategory category) const;
  // Jobs that are neither finished nor queued or running: what a resubmission runs.
  std::vector<int> unfinished() const;
};

SweepStatus sweep_status(const Plan& plan);

}  // namespace slamkit::sweep
