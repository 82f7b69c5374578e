#include "eval/regression/comparison.h"

#include <cmath>
#include <cstdio>

namespace slamkit::regress {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::kPass:
      return "pass";
    case Verdict::kImproved:
      return "improved";
    case Verdict::kRegressed:
      return "REGRESSED";
    case Verdict::kWarning:
      return "warning";
    case Verdict::kMissing:
      return "MISSING";
    case Verdict::kNew:
      return "no baseline";
    case Verdict::kOtherMachine:
      return "other machine";
  }
  return "";
}

bool is_failure(Verdict v) { return v == Verdict::kRegressed || v == Verdict::kMissing; }

MetricComparison compare_metric(const MetricInfo& metric, std::optional<double> value,
                                std::optional<double> baseline, const Tolerance& tolerance) {
  MetricComparison c;
  c.metric = &metric;
  c.value = value;
  c.baseline = baseline;
  if (!baseline) return c;  // kNew
  c.allowed = std::max(tolerance.abs, tolerance.rel * std::abs(*baseline));
  if (!value) {
    c.verdict = metric.warn_only ? Verdict::kWarning : Verdict::kMissing;
    return c;
  }
  const double worse = metric.higher_is_better ? *baseline - *value : *value - *baseline;
  // Values read back from JSON may differ from the written ones in the last bit.
  const double slack = 1e-12 * std::max(1.0, std::abs(*baseline));
  if (worse > c.allowed + slack)
    c.verdict = metric.warn_only ? Verdict::kWarning : Verdict::kRegressed;
  else if (-worse > c.allowed + slack)
    c.verdict = Verdict::kImproved;
  else
    c.verdict = Verdict::kPass;
  return c;
}

std::vector<MetricComparison> compare_metrics(const RunMetrics& run, const RunMetrics* baseline,
                                              const std::map<std::string, Tolerance>& tolerances,
                                              bool same_machine) {
  std::vector<MetricComparison> out;
  for (const MetricInfo& m : tracked_metrics()) {
    std::optional<double> value, base;
    if (auto it = run.find(m.key); it != run.end()) value = it->second;
    if (baseline)
      if (auto it = baseline->find(m.key); it != baseline->end()) base = it->second;
    if (!value && !base) continue;
    const auto tolerance = tolerances.find(m.key);
    MetricComparison c = compare_metric(
        m, value, base, tolerance != tolerances.end() ? tolerance->second : m.tolerance);
    if (m.warn_only && !same_machine && c.verdict != Verdict::kNew)
      c.verdict = Verdict::kOtherMachine;
    out.push_back(c);
  }
  return out;
}

namespace {

// Metres as millimetres-precise text; other units at the precision they are measured to.
std::string number_text(const MetricInfo& metric, double value, bool sign) {
  const char* format = "%.4f";
  if (metric.unit == "m") format = "%.5f";
  if (metric.unit == "frames") format = "%.0f";
  if (metric.unit == "s" || metric.unit == "frames/s") format = "%.1f";
  std::string f = std::string(sign ? "%+" : "%") + (format + 1);
  char text[64];
  std::snprintf(text, sizeof text, f.c_str(), value);
  return text;
}

}  // namespace

std::string format_value(const MetricInfo& metric, double value) {
  std::string text = number_text(metric, value, false);
  return metric.unit.empty() ? text : text + " " + metric.unit;
}

std::string format_delta(const MetricComparison& c) {
  if (!c.value || !c.baseline) return "";
  const double delta = *c.value - *c.baseline;
  std::string text = number_text(*c.metric, delta, true);
  if (!c.metric->unit.empty()) text += " " + c.metric->unit;
  if (*c.baseline != 0) {
    char percent[32];
    std::snprintf(percent, sizeof percent, " (%+.1f%%)", 100 * delta / std::abs(*c.baseline));
    text += percent;
  }
  return text;
}

}  // namespace slamkit::regress
