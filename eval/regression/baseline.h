#pragma once
// Baselines (results/baselines/<suite>/<entry>.json): an entry's metrics as a known-good run
// measured them, with where they came from (slamkit version, settings hash, machine, date).
#include <filesystem>
#include <optional>
#include <string>

#include "core/fingerprint.h"  // utc_now_iso for the records
#include "eval/regression/metrics.h"

namespace slamkit::regress {

struct Provenance {
  std::string version;        // `git describe --always --dirty --tags`, else the release
  std::string settings_hash;  // FNV-1a 64 of the run's settings.yaml
  std::string machine;        // CPU model, cores, kernel
  std::string date;           // UTC, ISO 8601
};

struct Baseline {
  Provenance provenance;
  std::string sequence;  // SequenceSource::describe()
  RunMetrics metrics;
};

// The baseline file format this slamkit writes and reads; a file without "format" predates the
// field and is format 1.
constexpr int kBaselineFormat = 1;

// Nothing when the file does not exist; InputError naming it when it is malformed or of another
// format.
std::optional<Baseline> read_baseline(const std::filesystem::path& file);
void write_baseline(const std::filesystem::path& file, const Baseline& baseline);

std::string slamkit_version();
std::string machine_description();

// Whether two machine_description()s name the same hardware (CPU model and cores): timing is
// comparable between them. The kernel is left out: it changes with every update, the hardware
// that sets the timing does not. An empty description (unknown) matches nothing.
bool same_machine(const std::string& a, const std::string& b);

}  // namespace slamkit::regress
