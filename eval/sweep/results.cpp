#include "eval/sweep/results.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "core/error.h"
#include "eval/regression/comparison.h"

namespace slamkit::sweep {
namespace {

std::string pair_key(const Job& job) {
  return job.entry + "|" + (job.seed ? std::to_string(*job.seed) : "-");
}

}  // namespace

int SweepResults::finished() const {
  int n = 0;
  for (const JobResult& r : jobs) n += r.status.category == TaskCategory::kDone && r.error.empty();
  return n;
}

std::optional<double> SweepResults::mean(const std::string& metric, const std::string& variant,
                                         const std::string& entry) const {
  double sum = 0;
  int n = 0;
  for (const JobResult& r : jobs) {
    if (r.job->variant != variant || r.job->entry != entry) continue;
    if (const auto it = r.metrics.find(metric); it != r.metrics.end()) {
      sum += it->second;
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

SweepResults collect_results(const Plan& plan, const SweepStatus& status) {
  SweepResults results;
  results.plan = &plan;
  results.status = status;
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    JobResult r;
    r.job = &plan.jobs[i];
    r.status = status.tasks.at(i);
    if (r.status.category == TaskCategory::kDone) {
      try {
        r.metrics = regress::read_run_metrics(plan.dir / r.job->run_folder);
      } catch (const InputError& e) {
        r.error = std::string("unreadable results: ") + e.what();
      }
    }
    results.jobs.push_back(std::move(r));
  }
  for (const std::string& key : plan.sweep.rank_by) {
    Ranking ranking = rank_variants(results, *regress::find_metric(key));
    if (ranking.pairs > 0) results.rankings.push_back(std::move(ranking));
  }
  return results;
}

Ranking rank_variants(const SweepResults& results, const regress::MetricInfo& metric) {
  const std::vector<Variant>& variants = results.plan->sweep.variants;
  // entry|seed -> the variants that have the metric there
  std::map<std::string, std::set<std::string>> have;
  for (const JobResult& r : results.jobs)
    if (r.metrics.count(metric.key)) have[pair_key(*r.job)].insert(r.job->variant);
  std::set<std::string> common;
  for (const auto& [pair, names] : have)
    if (names.size() == variants.size()) common.insert(pair);

  Ranking ranking;
  ranking.metric = &metric;
  ranking.pairs = int(common.size());
  if (common.empty()) return ranking;
  for (const Variant& v : variants) {
    double sum = 0;
    for (const JobResult& r : results.jobs)
      if (r.job->variant == v.name && common.count(pair_key(*r.job)))
        sum += r.metrics.at(metric.key);
    ranking.scores.push_back({v.name, sum / double(common.size())});
  }
  // Ties keep the file's order, so the ranking is the same on every machine.
  std::stable_sort(ranking.scores.begin(), ranking.scores.end(),
                   [&](const VariantScore& a, const VariantScore& b) {
                     return metric.higher_is_better ? a.mean > b.mean : a.mean < b.mean;
                   });
  return ranking;
}

std::string mean_text(const regress::MetricInfo& metric, double mean) {
  if (metric.unit != "frames") return regress::format_value(metric, mean);
  char text[32];
  std::snprintf(text, sizeof text, "%.2f frames", mean);
  return text;
}

}  // namespace slamkit::sweep
