#include "eval/regression/regression.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/error.h"
#include "eval/metrics/checksum.h"
#include "eval/regression/process.h"
#include "eval/regression/report.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

EntryResult evaluate_entry(const SuiteEntry& entry, const EntryRun& run, const fs::path& baselines,
                           const std::string& machine) {
  EntryResult r;
  r.entry = &entry;
  r.run = run;
  r.baseline = read_baseline(baselines / (entry.name + ".json"));
  r.baseline_same_machine = r.baseline && same_machine(r.baseline->provenance.machine, machine);
  if (!run.ok) return r;
  try {
    r.metrics = read_run_metrics(run.dir);
    if (fs::exists(run.dir / "settings.yaml"))
      r.settings_hash = eval::fnv1a64_file(run.dir / "settings.yaml");
  } catch (const InputError& e) {
    r.run.ok = false;
    r.run.error = std::string("unreadable results: ") + e.what();
    return r;
  }
  r.comparisons = compare_metrics(r.metrics, r.baseline ? &r.baseline->metrics : nullptr,
                                  entry.tolerances, r.baseline_same_machine);
  return r;
}

// Writes the baselines of the entries that ran and prints what changed from the old ones.
void update_baselines(const SuiteReport& report, const fs::path& dir) {
  for (const EntryResult& e : report.entries) {
    if (!e.run.ok) {
      std::printf("baseline    %s kept: the run failed\n", e.entry->name.c_str());
      continue;
    }
    Baseline b;
    b.provenance = report.current;
    b.provenance.settings_hash = e.settings_hash;
    b.sequence = e.entry->sequence.describe();
    b.metrics = e.metrics;
    write_baseline(dir / (e.entry->name + ".json"), b);
    if (!e.baseline) {
      std::printf("baseline    %s: new\n", e.entry->name.c_str());
      continue;
    }
    int changed = 0;
    for (const MetricComparison& c : e.comparisons) {
      if (c.value && c.baseline && *c.value == *c.baseline) continue;
      if (c.metric->warn_only) continue;  // timing moves on every run
      std::printf(
          "baseline    %s: %s %s -> %s (%s)\n", e.entry->name.c_str(), c.metric->label.c_str(),
          c.baseline ? format_value(*c.metric, *c.baseline).c_str() : "none",
          c.value ? format_value(*c.metric, *c.value).c_str() : "none", verdict_name(c.verdict));
      ++changed;
    }
    if (e.baseline->provenance.settings_hash != e.settings_hash)
      std::printf("baseline    %s: settings hash %s -> %s\n", e.entry->name.c_str(),
                  e.baseline->provenance.settings_hash.c_str(), e.settings_hash.c_str());
    if (changed == 0) std::printf("baseline    %s: metrics unchanged\n", e.entry->name.c_str());
  }
}

const char* machine_or_unknown(const std::string& machine) {
  return machine.empty() ? "an unrecorded machine" : machine.c_str();
}

void print_history_line(const fs::path& run_history, const fs::path& suite_history, bool recorded) {
  if (recorded)
    std::printf("history     %s, and recorded in %s\n", run_history.c_str(), suite_history.c_str());
  else
    std::printf("history     %s (%s unchanged: --record appends to it)\n", run_history.c_str(),
                suite_history.c_str());
}

void print_summary(const SuiteReport& report) {
  for (const EntryResult& e : report.entries) {
    if (!e.run.ok) {
      std::printf("ERROR       %s: %s\n", e.entry->name.c_str(), e.run.error.c_str());
      continue;
    }
    for (const MetricComparison& c : e.comparisons)
      if (is_failure(c.verdict) || c.verdict == Verdict::kWarning)
        std::printf("%-11s %s: %s %s, baseline %s, allowed %s\n", verdict_name(c.verdict),
                    e.entry->name.c_str(), c.metric->label.c_str(),
                    c.value ? format_value(*c.metric, *c.value).c_str() : "missing",
                    c.baseline ? format_value(*c.metric, *c.baseline).c_str() : "none",
                    format_value(*c.metric, c.allowed).c_str());
    if (!e.baseline && !report.baselines_updated)
      std::printf("note        %s: no baseline (--update-baselines writes it)\n",
                  e.entry->name.c_str());
    if (e.baseline && !e.baseline_same_machine)
      std::printf(
          "note        %s: timing not compared: the baseline was measured on %s, this is %s\n",
          e.entry->name.c_str(), machine_or_unknown(e.baseline->provenance.machine),
          report.current.machine.c_str());
  }
}

}  // namespace

std::vector<std::string> tum_names(const fs::path& script) {
  const auto listed = capture_output("bash", {script.string(), "--list"});
  if (!listed) throw_input_error(script.string(), "cannot list the TUM sequence names");
  std::vector<std::string> names;
  std::stringstream text(*listed);
  for (std::string name; text >> name;) names.push_back(name);
  return names;
}

fs::path default_download_script() {
  const char* env = std::getenv("SLAMKIT_DOWNLOAD_SCRIPT");
  if (env && *env) return env;
  return fs::path(SLAMKIT_SOURCE_DIR) / "datasets" / "download_tum.sh";
}

int run_regression(const RegressOptions& options) {
  SuiteContext context;
  context.data_dir = options.data_dir;
  context.presets = options.presets;
  context.download = options.download;
  context.tum_names = [&options] { return tum_names(options.download_script); };
  const Suite suite = load_suite(options.suite_file, context);
  const fs::path suite_dir = options.suite_file.parent_path();
  const fs::path baselines =
      options.baselines_dir.empty() ? suite_dir / "baselines" / suite.name : options.baselines_dir;
  const fs::path suite_history = suite_dir / "history.csv";
  const fs::path run_history =
      options.history_file.empty() ? options.out / "history.csv" : options.history_file;
  // Baselines are read before anything runs: a malformed one fails at once.
  for (const SuiteEntry& e : suite.entries) read_baseline(baselines / (e.name + ".json"));

  RunnerOptions runner;
  runner.slamkit = options.slamkit;
  runner.download_script = options.download_script;
  runner.out = options.out;
  runner.jobs = std::max(1, options.jobs);
  runner.threads = options.threads;
  runner.force = options.force;
  const std::vector<EntryRun> runs = run_entries(suite, runner);

  SuiteReport report;
  report.suite = &suite;
  report.out = options.out;
  report.current = {slamkit_version(), "", machine_description(), utc_now_iso()};
  for (size_t i = 0; i < suite.entries.size(); ++i)
    report.entries.push_back(
        evaluate_entry(suite.entries[i], runs[i], baselines, report.current.machine));

  if (options.update_baselines) {
    update_baselines(report, baselines);
    report.baselines_updated = true;
  }
  append_history(run_history, report);
  const bool record = options.record || options.update_baselines;
  if (record) append_history(suite_history, report);  // a run already in it is not added twice
  const bool run_history_is_tracked =
      fs::exists(suite_history) && fs::equivalent(suite_history, run_history);
  print_history_line(run_history, suite_history, record || run_history_is_tracked);
  // The trend: the tracked history, then this run's rows (the same rows twice draw once).
  std::vector<fs::path> histories;
  if (fs::exists(suite_history) && !run_history_is_tracked) histories.push_back(suite_history);
  histories.push_back(run_history);
  draw_suite_plots(histories, report);
  write_report_markdown(options.out / "report.md", report);
  write_report_html(options.out / "report.html", report);
  write_junit(options.out / "junit.xml", report);
  print_summary(report);

  int errors = 0;
  for (const EntryResult& e : report.entries) errors += !e.run.ok;
  const int failures = options.update_baselines ? errors : report.failures();
  std::printf("%s       %s: %zu entries, %d %s; report %s\n", failures ? "FAIL" : "PASS",
              suite.name.c_str(), suite.entries.size(), failures,
              options.update_baselines ? "failed to run" : "failed",
              (options.out / "report.html").c_str());
  return failures ? 1 : 0;
}

}  // namespace slamkit::regress
