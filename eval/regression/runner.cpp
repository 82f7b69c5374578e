#include "eval/regression/runner.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "core/error.h"
#include "eval/metrics/checksum.h"
#include "eval/metrics/metrics_json.h"
#include "eval/regression/baseline.h"
#include "eval/regression/process.h"
#include "eval/regression/run_folder.h"
#include "settings/settings_yaml.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::mutex print_mutex;

void say(const char* format, const std::string& a, const std::string& b = "") {
  std::lock_guard<std::mutex> lock(print_mutex);
  std::printf(format, a.c_str(), b.c_str());
  std::fflush(stdout);
}

// Calls work(i) for i in [0, n) on `jobs` threads.
template <class Work>
void parallel_for(size_t n, int jobs, Work work) {
  std::atomic<size_t> next{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, std::min(jobs, int(n))); ++t)
    threads.emplace_back([&] {
      for (size_t i; (i = next++) < n;) work(i);
    });
  for (std::thread& t : threads) t.join();
}

// Writes via a temporary file and a rename, so the file is either whole or absent. The
// temporary is this process's own: attempts of one job on several machines may write the same
// file (the job's settings) at once.
void write_atomically(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  const fs::path temp = file.string() + "." + host_and_pid() + ".tmp";
  {
    std::ofstream out(temp);
    out << text;
    if (!out) throw_input_error(temp.string(), "cannot write file");
  }
  fs::rename(temp, file);
}

std::string sequence_key(const SequenceSource& s) {
  if (s.kind == SequenceSource::Kind::kSynthetic)
    return "synthetic_" + s.preset + "_" + std::to_string(s.frames) + "_seed" +
           std::to_string(s.seed) + (s.sensor == "ideal" ? "" : "_" + s.sensor);
  return s.folder.string();
}

// A synthetic sequence is rendered once per output folder, into a folder of its own that is then
// renamed into place: the rename is the commit, so tasks on several machines may render the
// same sequence at once (a sweep on a cluster) and one copy wins. A TUM sequence goes through
// the download script, which fetches, checks and skips what is there.
struct SequenceJob {
  SequenceSource source;
  fs::path folder;
  std::string error;
};

// Removes what renders of `name` left in `dir` (temporary folders and logs "<name>.tmp.*"):
// called once the sequence is in place, when every other render of it is useless; a render
// still going on elsewhere then fails to write and finds the sequence in place.
void remove_leftover_renders(const fs::path& dir, const std::string& name) {
  std::error_code ignored;
  const std::string prefix = name + ".tmp.";
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ignored))
    if (e.path().filename().string().rfind(prefix, 0) == 0) fs::remove_all(e.path(), ignored);
}

void render_synthetic(SequenceJob& job, const RunnerOptions& options, int threads) {
  const SequenceSource& s = job.source;
  const fs::path dir = options.out / "sequences";
  const std::string name = sequence_key(s);
  job.folder = dir / name;
  if (fs::exists(job.folder)) return remove_leftover_renders(dir, name);
  const fs::path temp = dir / (name + ".tmp." + host_and_pid());
  const fs::path log = temp.string() + ".log";
  fs::remove_all(temp);
  say("render      %s\n", s.describe());
  const int code = run_logged(
      options.slamkit.string(),
      {"synth", "--preset", s.preset, "--frames", std::to_string(s.frames), "--seed",
       std::to_string(s.seed), "--sensor", s.sensor, "--threads", std::to_string(threads),
       "--out", temp.string()},
      log);
  if (code != 0 && !fs::exists(job.folder)) {
    job.error =
        "rendering failed (exit code " + std::to_string(code) + "; see " + log.string() + ")";
    return;
  }
  std::error_code lost_race;
  if (code == 0) fs::rename(log, dir / (name + ".log"), lost_race);
  if (code == 0) fs::rename(temp, job.folder, lost_race);
  if (lost_race && !fs::exists(job.folder))
    throw fs::filesystem_error("cannot rename", temp, job.folder, lost_race);
  remove_leftover_renders(dir, name);  // another task's copy in place: the same pixels
}

void prepare_sequence(SequenceJob& job, const RunnerOptions& options, int threads) {
  const SequenceSource& s = job.source;
  fs::create_directories(options.out / "sequences");
  if (s.kind == SequenceSource::Kind::kSynthetic) {
    render_synthetic(job, options, threads);
  } else if (s.kind == SequenceSource::Kind::kTum) {
    job.folder = s.folder;
    const fs::path log = options.out / "sequences" / (s.tum_name + ".download.log");
    fs::remove(log);
    say("fetch       %s into %s\n", s.tum_name, s.folder.parent_path().string());
    const int code = run_logged(
        "bash", {options.download_script.string(), s.folder.parent_path().string(), s.tum_name},
        log);
    if (code != 0)
      job.error = "download or check of " + s.tum_name + " failed (exit code " +
                  std::to_string(code) + "; see " + log.string() + ")";
  } else {
    job.folder = s.folder;
  }
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text;
}

// Whether `dir` holds a finished run of `fingerprint` (whole, as `slamkit run` wrote it); if so
// its marker's time and duration go into `run`. A run folder cut short after it was finished is
// reported under `label` (when not empty).
bool is_finished_run(const fs::path& dir, const std::string& fingerprint, EntryRun& run,
                     const std::string& label = "") {
  const fs::path marker = dir / kEntryMarker;
  if (!fs::exists(marker)) return false;
  try {
    const json done = json::parse(read_text(marker));
    if (done.value("fingerprint", "") != fingerprint) return false;
    eval::require_complete_run(dir);  // a later `slamkit run` there may have been cut
    run.ok = run.reused = true;
    run.finished = done.value("finished", "");
    run.seconds = done.value("seconds", 0.0);
    return true;
  } catch (const json::exception&) {
    return false;  // a damaged marker: the run is done again
  } catch (const InputError& e) {
    if (!label.empty()) say("run again   %s: %s\n", label, e.what());
    return false;
  }
}

// The attempt that published the run folder `dir` (its marker's "attempt"), or "".
std::string published_attempt(const fs::path& dir) {
  const json done = json::parse(read_text(dir / kEntryMarker), nullptr, false);
  return done.is_object() ? done.value("attempt", "") : "";
}

void run_request(const RunRequest& request, const fs::path& sequence,
                 const std::string& binary_hash, const RunnerOptions& options, int threads,
                 EntryRun& run) {
  const SuiteEntry& entry = *request.entry;
  run.dir = request.dir;
  const fs::path attempt = attempt_folder(run.dir);
  std::vector<std::string> args = {"run",       sequence.string(),      "--out", attempt.string(),
                                   "--threads", std::to_string(threads)};
  // What the run depends on besides the sequence: the settings and the executable.
  std::string fingerprint =
      entry.sequence.describe() + " | " + sequence.string() + " | slamkit " + binary_hash;
  if (entry.has_overrides) {
    const fs::path& settings = request.settings_file;
    write_atomically(settings, settings_yaml_text(entry.settings));
    fingerprint += " | settings " + eval::fnv1a64_file(settings);
    args.insert(args.end(), {"--settings", settings.string()});
  }
  if (entry.sequence.depth_scale) {
    char scale[32];
    std::snprintf(scale, sizeof scale, "%.17g", *entry.sequence.depth_scale);
    args.insert(args.end(), {"--depth-scale", scale});
  }
  if (!entry.sequence.calibration.empty())
    args.insert(args.end(), {"--calibration", entry.sequence.calibration.string()});

  if (!options.force && is_finished_run(run.dir, fingerprint, run, entry.name)) {
    say("reuse       %s (finished %s)\n", request.label, run.finished);
    return;
  }
  // A finished run found at publication that was not there now was published by another
  // attempt of this job meanwhile (under --force the one there now is replaced).
  const std::string replaced = published_attempt(run.dir);
  if (const int stale = remove_stale_attempts(run.dir))
    say("clean       %s: %s attempt folder(s) of a dead attempt removed\n", request.label,
        std::to_string(stale));
  fs::create_directories(attempt);
  say("run         %s (log %s)\n", request.label, (attempt / "run.log").string());
  const auto start = std::chrono::steady_clock::now();
  const int code = run_logged(options.slamkit.string(), args, attempt / "run.log");
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (code != 0) {
    keep_failed_attempt(attempt, run.dir);
    run.error = "slamkit run exited with code " + std::to_string(code) + " (see " +
                (failed_folder(run.dir) / "run.log").string() + ")";
    say("FAILED      %s: %s\n", request.label, run.error);
    return;
  }
  run.ok = true;
  run.finished = utc_now_iso();
  const json done = {{"entry", entry.name},
                     {"fingerprint", fingerprint},
                     {"finished", run.finished},
                     {"seconds", run.seconds},
                     {"attempt", attempt.filename().string()},
                     {"command", args}};
  write_atomically(attempt / kEntryMarker, done.dump(2) + "\n");
  const Publication published = publish_attempt(attempt, run.dir, [&](const fs::path& dir) {
    EntryRun other;
    return is_finished_run(dir, fingerprint, other) && published_attempt(dir) != replaced;
  });
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f", run.seconds);
  if (published == Publication::kPublishedByAnother) {
    is_finished_run(run.dir, fingerprint, run);
    say("duplicate   %s: another attempt published it first; this one's copy is discarded\n",
        request.label);
    return;
  }
  say("done        %s in %s s\n", request.label, seconds);
}

}  // namespace

std::vector<EntryRun> run_requests(const std::vector<RunRequest>& requests,
                                   const RunnerOptions& options) {
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = options.threads > 0 ? options.threads : std::max(1, cores / options.jobs);

  std::map<std::string, size_t> index;
  std::vector<SequenceJob> sequences;
  for (const RunRequest& r : requests)
    if (index.emplace(sequence_key(r.entry->sequence), sequences.size()).second)
      sequences.push_back({r.entry->sequence, {}, {}});
  parallel_for(sequences.size(), options.jobs, [&](size_t i) {
    try {
      prepare_sequence(sequences[i], options, threads);
    } catch (const std::exception& e) {
      sequences[i].error = e.what();
    }
  });

  const std::string binary_hash = eval::fnv1a64_file(options.slamkit);
  std::vector<EntryRun> runs(requests.size());
  parallel_for(runs.size(), options.jobs, [&](size_t i) {
    const RunRequest& request = requests[i];
    const SequenceJob& sequence = sequences[index.at(sequence_key(request.entry->sequence))];
    runs[i].dir = request.dir;
    if (!sequence.error.empty()) {
      runs[i].error = sequence.error;
      return;
    }
    try {
      run_request(request, sequence.folder, binary_hash, options, threads, runs[i]);
    } catch (const std::exception& e) {
      runs[i].ok = false;
      runs[i].error = e.what();
    }
  });
  return runs;
}

std::vector<EntryRun> run_entries(const Suite& suite, const RunnerOptions& options) {
  std::vector<RunRequest> requests;
  for (const SuiteEntry& e : suite.entries)
    requests.push_back(
        {&e, e.name, options.out / "runs" / e.name, options.out / "settings" / (e.name + ".yaml")});
  return run_requests(requests, options);
}

std::string fetch_tum_sequences(const std::vector<RunRequest>& requests,
                                const RunnerOptions& options) {
  std::set<std::string> fetched;
  for (const RunRequest& r : requests) {
    if (r.entry->sequence.kind != SequenceSource::Kind::kTum) continue;
    if (!fetched.insert(r.entry->sequence.tum_name).second) continue;
    SequenceJob job{r.entry->sequence, {}, {}};
    prepare_sequence(job, options, 1);
    if (!job.error.empty()) return job.error;
  }
  return "";
}

}  // namespace slamkit::regress
