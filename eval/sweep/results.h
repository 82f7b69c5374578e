#pragma once
// A sweep's finished runs as data: each job's tracked metrics (read as the regression runner
// reads them), the mean of a metric per variant and entry over the seeds, and the variants
// ranked by each of the sweep's rank_by metrics.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "eval/regression/metrics.h"
#include "eval/sweep/plan.h"
#include "eval/sweep/status.h"

namespace slamkit::sweep {

struct JobResult {
  const Job* job = nullptr;
  TaskStatus status;
  regress::RunMetrics metrics;  // of a done job
  std::string error;            // a done job whose results cannot be read
};

struct VariantScore {
  std::string variant;
  double mean = 0;
};

// Variants by one metric, best first. Each is scored over the same runs: the entry and seed
// pairs that every variant finished with the metric, so a missing run favours none.
struct Ranking {
  const regress::MetricInfo* metric = nullptr;
  std::vector<VariantScore> scores;
  int pairs = 0;  // entry and seed pairs compared
};

struct SweepResults {
  const Plan* plan = nullptr;
  SweepStatus status;
  std::vector<JobResult> jobs;    // in index order
  std::vector<Ranking> rankings;  // one per rank_by metric with pairs > 0

  int finished() const;  // done with readable metrics
  // The mean over seeds of `metric` for a variant and entry; nothing when no seed has it.
  std::optional<double> mean(const std::string& metric, const std::string& variant,
                             const std::string& entry) const;
};

SweepResults collect_results(const Plan& plan, const SweepStatus& status);

Ranking rank_variants(const SweepResults& results, const regress::MetricInfo& metric);

// A mean of a metric as text: as the regression report writes values, but counts of frames with
// two decimals (a mean of 0.25 lost frames is not 0).
std::string mean_text(const regress::MetricInfo& metric, double mean);

}  // namespace slamkit::sweep
