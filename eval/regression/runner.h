#pragma once
// Runs a suite's entries (or a sweep's jobs): each sequence made ready (rendered, or downloaded
// and checked), then `slamkit run` per entry as a child process, `jobs` at a time. A run folder
// counts as finished only once regress_entry.json is written, after the run succeeded: an
// interrupted suite resumes where it stopped and never reads half-written outputs.
#include <filesystem>
#include <string>
#include <vector>

#include "eval/regression/suite.h"

namespace slamkit::regress {

struct RunnerOptions {
  std::filesystem::path slamkit;          // the executable
  std::filesystem::path download_script;  // datasets/download_tum.sh
  std::filesystem::path out;              // sequences/ (and run_entries' runs/, settings/)
  int jobs = 1;
  int threads = 0;     // per run; 0: the cores shared out among the jobs
  bool force = false;  // run again even when a finished run folder matches
};

struct EntryRun {
  std::filesystem::path dir;
  bool ok = false;
  bool reused = false;
  std::string error;     // when not ok: what failed, naming the log to read
  std::string finished;  // UTC time the run finished (from the marker)
  double seconds = 0;    // wall time of the child
};

// The marker a finished run folder holds.
inline const char* kEntryMarker = "regress_entry.json";

// One run to make: what to run and where its files go.
struct RunRequest {
  const SuiteEntry* entry = nullptr;    // the sequence and the settings
  std::string label;                    // for progress lines
  std::filesystem::path dir;            // the run folder
  std::filesystem::path settings_file;  // written when the entry has overrides; outside dir
};

// One result per request, in order. Progress goes to stdout.
std::vector<EntryRun> run_requests(const std::vector<RunRequest>& requests,
                                   const RunnerOptions& options);

// A suite's entries into runs/<entry>/ with settings/<entry>.yaml, in suite order.
std::vector<EntryRun> run_entries(const Suite& suite, const RunnerOptions& options);

// Downloads the TUM sequences of the requests that are not in place yet (before handing runs
// to machines without a network); "" or what failed.
std::string fetch_tum_sequences(const std::vector<RunRequest>& requests,
                                const RunnerOptions& options);

}  // namespace slamkit::regress
