#pragma once
// Where each job of a sweep stands, from its run folder and, for a sweep handed to Slurm, from
// Slurm's word on its array task: done (its run folder is published: eval/regression/run_folder.h),
// pending or running (Slurm, or the attempt's run.json for a run on this machine), requeued
// (Slurm runs it again after an attempt died with its node or was preempted), failed (it ended
// without a finished run: its run failed, it was cancelled, ran out of time or memory) or missing
// (no trace of it).
#include <filesystem>
#include <string>
#include <vector>

#include "eval/sweep/plan.h"
#include "eval/sweep/slurm.h"

namespace slamkit::sweep {

enum class TaskCategory { kDone, kPending, kRunning, kRequeued, kFailed, kMissing };
const char* category_name(TaskCategory category);  // "done", "pending", ...

// The category from what the run folder holds and what Slurm says (state empty: nothing).
// folder_status: "" (no trace), run.json's status, or "started" (a folder without it).
TaskCategory classify(bool finished, const std::string& folder_status, const TaskState& slurm);

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
  // Jobs that are neither finished nor queued, requeued or running: what a resubmission runs.
  std::vector<int> unfinished() const;
};

SweepStatus sweep_status(const Plan& plan);

}  // namespace slamkit::sweep
