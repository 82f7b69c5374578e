#include "eval/sweep/slurm.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/fingerprint.h"
#include "eval/regression/process.h"
#include "io/atomic_file.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;

fs::path slurm_dir(const fs::path& dir) { return dir / "slurm"; }
fs::path submissions_file(const fs::path& dir) { return slurm_dir(dir) / "submissions.tsv"; }

std::string read_text(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  return parts;
}

bool is_number(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), ::isdigit);
}

// For a shell script: the text in single quotes.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string array_script(const Plan& plan, const std::string& array, const SlurmOptions& options,
                         const fs::path& slamkit) {
  const fs::path dir = fs::absolute(plan.dir);
  std::string s = "#!/bin/bash\n";
  s += "# slamkit sweep " + plan.sweep.name + ": array task i runs job i of " +
       (dir / "jobs.tsv").string() + ".\n";
  s += "# Written by `slamkit sweep run --backend slurm`, submitted with sbatch.\n";
  s += "#SBATCH --job-name=slamkit-" + plan.sweep.name + "\n";
  s += "#SBATCH --array=" + array + "\n";
  s += "#SBATCH --time=" + options.time + "\n";
  s += "#SBATCH --mem=" + options.memory + "\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(options.cpus) + "\n";
  s += "#SBATCH --output=" + (slurm_dir(dir) / "logs" / "%A_%a.log").string() + "\n";
  // Requeued when its node fails or it is preempted; a requeued attempt appends to the log.
  s += "#SBATCH --requeue\n";
  s += "#SBATCH --open-mode=append\n";
  if (!options.partition.empty()) s += "#SBATCH --partition=" + options.partition + "\n";
  s += "exec " + quoted(fs::absolute(slamkit).string()) + " sweep task " + quoted(dir.string()) +
       " \"$SLURM_ARRAY_TASK_ID\" --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  return s;
}

// The id in sbatch --parsable's answer ("12" or "12;cluster"), which ends its output.
std::string parsable_job_id(const std::string& output) {
  std::string id;
  for (const std::string& line : split(output, '\n')) {
    const std::string first = split(line, ';').empty() ? "" : split(line, ';')[0];
    if (is_number(first)) id = first;
  }
  return id;
}

// "12_3" -> ("12", 3); false for anything else ("12", "12_[4-7%2]", "12.batch").
bool split_task_id(const std::string& id, std::string& job, int& index) {
  const size_t underscore = id.find('_');
  if (underscore == std::string::npos) return false;
  job = id.substr(0, underscore);
  const std::string task = id.substr(underscore + 1);
  if (!is_number(job) || !is_number(task)) return false;
  index = std::stoi(task);
  return true;
}

// "CANCELLED by 0" -> "CANCELLED".
std::string first_word(const std::string& text) {
  std::stringstream in(text);
  std::string word;
  in >> word;
  return word;
}

std::string joined_ids(const std::vector<Submission>& submissions) {
  std::string ids;
  for (const Submission& s : submissions) ids += (ids.empty() ? "" : ",") + s.job_id;
  return ids;
}

}  // namespace

std::string array_spec(const std::vector<int>& indices, int max_running) {
  std::vector<int> sorted = indices;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::string spec;
  for (size_t i = 0; i < sorted.size();) {
    size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
    spec += (spec.empty() ? "" : ",") + std::to_string(sorted[i]);
    if (j > i) spec += "-" + std::to_string(sorted[j]);
    i = j + 1;
  }
  if (max_running > 0) spec += "%" + std::to_string(max_running);
  return spec;
}

std::vector<int> array_indices(const std::string& spec) {
  std::vector<int> indices;
  for (const std::string& part : split(spec.substr(0, spec.find('%')), ',')) {
    const std::vector<std::string> ends = split(part, '-');
    if (ends.empty() || ends.size() > 2 || !std::all_of(ends.begin(), ends.end(), is_number))
      continue;
    const int first = std::stoi(ends[0]), last = std::stoi(ends.back());
    for (int i = first; i <= last; ++i) indices.push_back(i);
  }
  return indices;
}

Submission submit_array(const Plan& plan, const std::vector<int>& indices,
                        const SlurmOptions& options, const fs::path& slamkit) {
  const fs::path dir = slurm_dir(plan.dir);
  fs::create_directories(dir / "logs");
  Submission submission;
  submission.array = array_spec(indices, options.max_running);
  const fs::path script = dir / "sweep.sbatch";
  write_file_atomically(script, [&](std::ostream& out) {
    out << array_script(plan, submission.array, options, slamkit);
  });
  const fs::path log = dir / "sbatch.log";
  fs::remove(log);
  const int code = regress::run_logged("sbatch", {"--parsable", script.string()}, log);
  const std::string output = read_text(log);
  if (code == -1 || code == 127)
    throw std::runtime_error("sbatch not found: submit from a machine with Slurm's commands");
  submission.job_id = parsable_job_id(output);
  if (code != 0 || submission.job_id.empty())
    throw std::runtime_error("sbatch refused " + script.string() + " (exit code " +
                             std::to_string(code) + "): " + output);
  submission.submitted = utc_now_iso();
  std::ofstream(submissions_file(plan.dir), std::ios::app)
      << submission.job_id << "\t" << submission.array << "\t" << submission.submitted << "\n";
  return submission;
}

std::vector<Submission> read_submissions(const fs::path& dir) {
  std::vector<Submission> submissions;
  std::ifstream in(submissions_file(dir));
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = split(line, '\t');
    if (f.size() == 3 && is_number(f[0])) submissions.push_back({f[0], f[1], f[2]});
  }
  return submissions;
}

ArrayStates parse_squeue(const std::string& text) {
  ArrayStates states;
  for (const std::string& line : split(text, '\n')) {
    const std::vector<std::string> f = split(line, '|');
    if (f.size() == 3 && is_number(f[0]) && is_number(f[1]))
      states[f[0]][std::stoi(f[1])].state = first_word(f[2]);
  }
  return states;
}

ArrayStates parse_sacct(const std::string& text) {
  ArrayStates states;
  for (const std::string& line : split(text, '\n')) {
    const std::vector<std::string> f = split(line, '|');
    std::string job;
    int index = 0;
    if (f.size() < 2 || !split_task_id(f[0], job, index)) continue;
    // Attempts are listed oldest first: the last is the task's state now.
    const auto [task, first] = states[job].try_emplace(index);
    if (!first) ++task->second.restarts;
    task->second.state = first_word(f[1]);
  }
  return states;
}

ArrayStates parse_scontrol(const std::string& text) {
  ArrayStates states;
  for (const std::string& line : split(text, '\n')) {
    std::map<std::string, std::string> fields;
    std::stringstream words(line);
    for (std::string word; words >> word;) {
      const size_t equals = word.find('=');
      if (equals != std::string::npos) fields[word.substr(0, equals)] = word.substr(equals + 1);
    }
    const std::string job = fields["ArrayJobId"], task = fields["ArrayTaskId"];
    if (!is_number(job) || !is_number(task) || fields["JobState"].empty()) continue;
    TaskState& state = states[job][std::stoi(task)];
    state.state = fields["JobState"];
    if (is_number(fields["Restarts"])) state.restarts = std::stoi(fields["Restarts"]);
  }
  return states;
}

SlurmStates query_slurm(const std::vector<Submission>& submissions) {
  SlurmStates result;
  if (submissions.empty()) return result;
  // Finished tasks first, live ones over them: a live state is the newest word.
  ArrayStates ended;
  if (auto sacct = regress::capture_output(
          "sacct", {"-n", "-P", "-X", "-D", "-j", joined_ids(submissions), "-o", "JobID,State"})) {
    ended = parse_sacct(*sacct);
    result.source = "squeue and sacct";
  } else {
    for (const Submission& s : submissions)
      if (auto shown = regress::capture_output("scontrol", {"-o", "show", "job", s.job_id}))
        for (const auto& [job, tasks] : parse_scontrol(*shown)) ended[job] = tasks;
    result.source = "squeue and scontrol (sacct has no accounting storage here)";
  }
  const auto live = regress::capture_output("squeue", {"-h", "-r", "--me", "-o", "%F|%K|%T"});
  if (!live) result.source = "nothing: squeue did not answer";
  const ArrayStates queued = live ? parse_squeue(*live) : ArrayStates{};
  for (const Submission& s : submissions) {  // in order: a resubmission overrides
    for (const int index : array_indices(s.array)) {
      result.tasks.erase(index);
      for (const ArrayStates* states : {&std::as_const(ended), &queued}) {
        const auto job = states->find(s.job_id);
        if (job == states->end()) continue;
        const auto task = job->second.find(index);
        if (task == job->second.end()) continue;
        TaskState& state = result.tasks[index];
        state.state = task->second.state;  // the live word over the accounted one
        state.restarts = std::max(state.restarts, task->second.restarts);
        state.job = s.job_id + "_" + std::to_string(index);
      }
    }
  }
  return result;
}

fs::path task_log(const fs::path& dir, const std::string& job_id, int index) {
  return slurm_dir(dir) / "logs" / (job_id + "_" + std::to_string(index) + ".log");
}

}  // namespace slamkit::sweep
