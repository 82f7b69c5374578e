#include "eval/sweep/commands.h"

#include <cstdio>

#include "core/error.h"
#include "eval/sweep/results.h"
#include "eval/sweep/status.h"
#include "eval/sweep/sweep_report.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;

regress::RunnerOptions runner_options(const Plan& plan, int jobs, int threads,
                                      const SweepEnvironment& env) {
  regress::RunnerOptions options;
  options.slamkit = env.slamkit;
  options.download_script = env.download_script;
  options.out = plan.dir;
  options.jobs = std::max(1, jobs);
  options.threads = threads;
  return options;
}

std::string seeds_text(const Sweep& sweep) {
  if (sweep.seeds.empty()) return "the suite's seeds";
  std::string text;
  for (const uint64_t s : sweep.seeds) text += (text.empty() ? "" : ", ") + std::to_string(s);
  return std::to_string(sweep.seeds.size()) + " seeds (" + text + ")";
}

// One line per job that is not finished: what it is, Slurm's word and the log to read.
void print_unfinished(const Plan& plan, const SweepStatus& status) {
  for (const TaskStatus& t : status.tasks) {
    if (t.category == TaskCategory::kDone) continue;
    std::printf("%-8s %4d  %s", category_name(t.category), t.index,
                plan.jobs[t.index].label().c_str());
    if (!t.slurm.state.empty())
      std::printf("  %s (%s)", t.slurm.state.c_str(), t.slurm.job.c_str());
    if (t.slurm.restarts > 0)
      std::printf("  requeued %d time%s", t.slurm.restarts, t.slurm.restarts == 1 ? "" : "s");
    if (!t.log.empty()) std::printf("  log %s", t.log.c_str());
    std::printf("\n");
  }
}

std::string counts_text(const SweepStatus& s) {
  std::string text;
  for (const TaskCategory c : {TaskCategory::kDone, TaskCategory::kPending, TaskCategory::kRunning,
                               TaskCategory::kRequeued, TaskCategory::kFailed,
                               TaskCategory::kMissing})
    text += (text.empty() ? "" : ", ") + std::to_string(s.count(c)) + " " + category_name(c);
  return text;
}

}  // namespace

int plan_sweep(const fs::path& sweep_file, const fs::path& dir, const SweepEnvironment& env) {
  const Plan plan = write_plan(sweep_file, dir, env.suite);
  const Sweep& sw = plan.sweep;
  std::printf("plan        %s: %zu entries x %zu variants x %s = %zu jobs\n", sw.name.c_str(),
              sw.suite.entries.size(), sw.variants.size(), seeds_text(sw).c_str(),
              plan.jobs.size());
  for (const Variant& v : sw.variants) {
    std::string keys;
    for (const SettingOverride& o : v.overrides)
      keys += (keys.empty() ? "" : ", ") + o.key + ": " + YAML::Dump(o.value);
    std::printf("variant     %s%s%s\n", v.name.c_str(), keys.empty() ? "" : ": ", keys.c_str());
  }
  std::printf("wrote       %s\n", (dir / "jobs.tsv").c_str());
  return 0;
}

int run_local(const fs::path& dir, int jobs, int threads, const SweepEnvironment& env) {
  const Plan plan = load_plan(dir, env.suite);
  const std::vector<regress::EntryRun> runs =
      regress::run_requests(plan.requests(), runner_options(plan, jobs, threads, env));
  int failed = 0, reused = 0;
  for (const regress::EntryRun& r : runs) {
    failed += !r.ok;
    reused += r.reused;
  }
  std::printf(
      "local       %zu jobs: %zu finished (%d reused), %d failed; next: slamkit sweep "
      "collect %s\n",
      runs.size(), runs.size() - size_t(failed), reused, failed, dir.c_str());
  return failed ? 1 : 0;
}

int run_slurm(const fs::path& dir, const SlurmOptions& options, bool resubmit_missing,
              const SweepEnvironment& env) {
  const Plan plan = load_plan(dir, env.suite);
  const SweepStatus status = sweep_status(plan);
  if (!status.submissions.empty() && !resubmit_missing)
    throw_input_error((dir / "slurm" / "submissions.tsv").string(),
                      "this sweep was submitted before (array job " +
                          status.submissions.back().job_id +
                          "): `--resubmit-missing` submits the tasks that did not finish");
  std::vector<int> indices;
  if (resubmit_missing) {
    indices = status.unfinished();
  } else {
    for (const TaskStatus& t : status.tasks)
      if (t.category != TaskCategory::kDone) indices.push_back(t.index);
  }
  if (indices.empty()) {
    std::printf("slurm       nothing to submit: %s\n", counts_text(status).c_str());
    return 0;
  }
  const std::vector<regress::RunRequest> requests = plan.requests();
  const std::string fetch_error =
      regress::fetch_tum_sequences(requests, runner_options(plan, 1, 1, env));
  if (!fetch_error.empty()) {
    std::fprintf(stderr, "slamkit: error: %s\n", fetch_error.c_str());
    return 1;
  }
  const Submission s = submit_array(plan, indices, options, env.slamkit);
  std::printf(
      "slurm       submitted array job %s: %zu tasks (--array=%s), %s per task, %d CPUs, "
      "%s memory\n",
      s.job_id.c_str(), indices.size(), s.array.c_str(), options.time.c_str(), options.cpus,
      options.memory.c_str());
  std::printf("slurm       script %s; logs %s\n", (dir / "slurm" / "sweep.sbatch").c_str(),
              task_log(dir, s.job_id, 0).parent_path().c_str());
  std::printf("next        slamkit sweep status %s; slamkit sweep collect %s\n", dir.c_str(),
              dir.c_str());
  return 0;
}

int run_task(const fs::path& dir, int index, int threads, const SweepEnvironment& env) {
  const Plan plan = load_plan(dir, env.suite);
  if (index < 0 || size_t(index) >= plan.jobs.size())
    throw_input_error((dir / "jobs.tsv").string(), "no job " + std::to_string(index) +
                                                       " (the plan has 0.." +
                                                       std::to_string(plan.jobs.size() - 1) + ")");
  std::printf("task        %d: %s\n", index, plan.jobs[index].label().c_str());
  std::fflush(stdout);  // into Slurm's log before a cancellation can end the task
  const regress::EntryRun run =
      regress::run_requests({plan.request(size_t(index))}, runner_options(plan, 1, threads, env))
          .front();
  if (!run.ok) std::fprintf(stderr, "slamkit: error: %s\n", run.error.c_str());
  return run.ok ? 0 : 1;
}

int print_status(const fs::path& dir, const SweepEnvironment& env) {
  const Plan plan = load_plan(dir, env.suite);
  const SweepStatus status = sweep_status(plan);
  std::printf("status      %s: %zu jobs: %s", plan.sweep.name.c_str(), plan.jobs.size(),
              counts_text(status).c_str());
  if (!status.submissions.empty()) {
    std::string ids;
    for (const Submission& s : status.submissions) ids += (ids.empty() ? "" : ", ") + s.job_id;
    std::printf(" (array jobs %s; Slurm states from %s)", ids.c_str(), status.slurm_source.c_str());
  }
  std::printf("\n");
  print_unfinished(plan, status);
  if (!status.unfinished().empty() && !status.submissions.empty())
    std::printf("resubmit    slamkit sweep run %s --backend slurm --resubmit-missing\n",
                dir.c_str());
  return 0;
}

int collect_sweep(const fs::path& dir, bool allow_incomplete, const SweepEnvironment& env) {
  const Plan plan = load_plan(dir, env.suite);
  const SweepStatus status = sweep_status(plan);
  if (status.count(TaskCategory::kDone) != int(plan.jobs.size()) && !allow_incomplete) {
    std::printf("INCOMPLETE  %d of %zu runs finished: %s; nothing merged\n",
                status.count(TaskCategory::kDone), plan.jobs.size(), counts_text(status).c_str());
    print_unfinished(plan, status);
    const std::string again = status.submissions.empty()
                                  ? "slamkit sweep run " + dir.string()
                                  : "slamkit sweep run " + dir.string() +
                                        " --backend slurm --resubmit-missing";
    std::printf("then        wait for them, or run the failed and missing ones again (%s); "
                "`collect --allow-incomplete` merges what there is\n",
                again.c_str());
    return 1;
  }
  const SweepResults results = collect_results(plan, status);
  const SweepReportFiles files = write_sweep_report(results);
  for (const Ranking& k : results.rankings) {
    const VariantScore& best = k.scores.front();
    std::printf("best        %s: %s (%s", k.metric->label.c_str(), best.variant.c_str(),
                mean_text(*k.metric, best.mean).c_str());
    if (k.scores.size() > 1)
      std::printf("; runner-up %s %s", k.scores[1].variant.c_str(),
                  mean_text(*k.metric, k.scores[1].mean).c_str());
    std::printf("; mean of %d runs each)\n", k.pairs);
  }
  print_unfinished(plan, results.status);
  const int total = int(plan.jobs.size()), finished = results.finished();
  std::printf("%-11s %d of %d runs; report %s, %s, %s%s%s\n",
              finished == total ? "COMPLETE" : "INCOMPLETE", finished, total,
              files.markdown.c_str(), files.html.c_str(), files.runs_csv.c_str(),
              files.heatmap.empty() ? "" : ", ", files.heatmap.c_str());
  return finished == total ? 0 : 1;
}

}  // namespace slamkit::sweep
