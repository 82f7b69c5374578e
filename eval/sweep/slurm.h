#pragma once
// The Slurm side of a sweep, through Slurm's own commands: a job-array script with one
// `slamkit sweep task DIR INDEX` per array task, `sbatch` to submit it, and the tasks' states
// from `squeue` (queued and running), `sacct` (finished, where accounting is on) and, where
// sacct has no accounting storage to read, `scontrol show job` (finished in the last minutes).
// Every submission is recorded in DIR/slurm/submissions.tsv.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "eval/sweep/plan.h"

namespace slamkit::sweep {

struct SlurmOptions {
  std::string time = "01:00:00";  // per task, as sbatch's --time takes it
  std::string memory = "4G";      // per task, as sbatch's --mem takes it
  int cpus = 2;                   // per task; the run's thread count
  int max_running = 32;           // array tasks running at once (the %M of --array)
  std::string partition;          // empty: the cluster's default
};

struct Submission {
  std::string job_id;     // the array job's id
  std::string array;      // as given to --array: "0-7%4", "3,5%4"
  std::string submitted;  // UTC
};

// "0-3,5,7-9" for {0,1,2,3,5,7,8,9}, with "%M" when max_running > 0.
std::string array_spec(const std::vector<int>& indices, int max_running);
// The indices an --array value names (the %M dropped).
std::vector<int> array_indices(const std::string& spec);

// Writes DIR/slurm/sweep.sbatch for the given tasks, submits it with sbatch, records and
// returns the submission. std::runtime_error with sbatch's words when it refuses.
Submission submit_array(const Plan& plan, const std::vector<int>& indices,
                        const SlurmOptions& options, const std::filesystem::path& slamkit);

std::vector<Submission> read_submissions(const std::filesystem::path& dir);

// Slurm's word on an array task: its state (RUNNING, PENDING, COMPLETED, CANCELLED, TIMEOUT,
// ...), how often Slurm requeued it (a node failed under it, it was preempted) and the job it
// runs as, "12_3".
struct TaskState {
  std::string state;
  int restarts = 0;
  std::string job;
};

struct SlurmStates {
  std::map<int, TaskState> tasks;  // by job index; the latest submission of each task wins
  std::string source;              // which commands answered, for the user
};

// Asks squeue, then sacct (or scontrol when sacct has no accounting), about the submissions.
SlurmStates query_slurm(const std::vector<Submission>& submissions);

// The parsers behind query_slurm, over the commands' text:
//   squeue -h -r --me -o '%F|%K|%T'              12|3|RUNNING
//   sacct -n -P -X -D -j ID,... -o JobID,State   12_3|NODE_FAIL
//                                                12_3|PENDING   (-D: one line per attempt)
//   scontrol -o show job ID                      JobId=15 ArrayJobId=12 ArrayTaskId=3 ...
//   JobState=... Restarts=1
// Each gives array job id -> index -> state (the job left empty); lines of other jobs or of
// pending ranges are passed over.
using ArrayStates = std::map<std::string, std::map<int, TaskState>>;
ArrayStates parse_squeue(const std::string& text);
ArrayStates parse_sacct(const std::string& text);
ArrayStates parse_scontrol(const std::string& text);

// The log file Slurm writes for a task (the script's --output).
std::filesystem::path task_log(const std::filesystem::path& dir, const std::string& job_id,
                               int index);

}  // namespace slamkit::sweep
