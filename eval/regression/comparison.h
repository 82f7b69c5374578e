#pragma once
// A run's metrics against its baseline, metric by metric, with the suite's tolerances.
#include <optional>
#include <string>
#include <vector>

#include "eval/regression/metrics.h"

namespace slamkit::regress {

enum class Verdict {
  kPass,          // within tolerance
  kImproved,      // better than the baseline by more than the tolerance (update the baseline)
  kRegressed,     // worse by more than the tolerance: the suite fails
  kWarning,       // a warn-only metric (timing) worse by more than its tolerance
  kMissing,       // in the baseline but not in the run: the suite fails
  kNew,           // no baseline value to compare with
  kOtherMachine,  // timing against a baseline measured on other hardware: shown, not judged
};
const char* verdict_name(Verdict v);  // "pass", "improved", "REGRESSED", ...
bool is_failure(Verdict v);

struct MetricComparison {
  const MetricInfo* metric = nullptr;
  std::optional<double> value, baseline;
  double allowed = 0;  // how much worse the value may be than the baseline
  Verdict verdict = Verdict::kNew;
};

MetricComparison compare_metric(const MetricInfo& metric, std::optional<double> value,
                                std::optional<double> baseline, const Tolerance& tolerance);

// Every tracked metric that the run or the baseline has, in report order. Without
// `same_machine` the timing metrics are kOtherMachine rather than judged.
std::vector<MetricComparison> compare_metrics(const RunMetrics& run, const RunMetrics* baseline,
                                              const std::map<std::string, Tolerance>& tolerances,
                                              bool same_machine);

// "0.0123 m" with the digits a metric needs: millimetres for metres, whole frames, ...
std::string format_value(const MetricInfo& metric, double value);
std::string format_delta(const MetricComparison& c);  // "+0.0004 m (+3.2%)"

}  // namespace slamkit::regress
