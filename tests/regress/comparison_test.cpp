// Tolerances: a metric may get worse by max(abs, rel * |baseline|); timing only warns.
#include "eval/regression/comparison.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "eval/regression/baseline.h"
#include "eval/regression/metrics.h"
#include "support/test_data.h"

namespace slamkit::regress {
namespace {

TEST(Comparison, ToleranceIsTheLargerOfAbsoluteAndRelative) {
  const MetricInfo& ate = *find_metric("ate_rmse");
  const Tolerance t{0.001, 0.10};
  EXPECT_EQ(compare_metric(ate, 0.0059, 0.005, t).verdict, Verdict::kPass);  // abs allows 1 mm
  EXPECT_EQ(compare_metric(ate, 0.0061, 0.005, t).verdict, Verdict::kRegressed);
  EXPECT_EQ(compare_metric(ate, 0.054, 0.050, t).verdict, Verdict::kPass);  // rel allows 5 mm
  EXPECT_EQ(compare_metric(ate, 0.056, 0.050, t).verdict, Verdict::kRegressed);
  EXPECT_EQ(compare_metric(ate, 0.044, 0.050, t).verdict, Verdict::kImproved);
  EXPECT_DOUBLE_EQ(compare_metric(ate, 0.056, 0.050, t).allowed, 0.005);
}

TEST(Comparison, DirectionWarningsMissingAndNew) {
  const Tolerance t{0.02, 0};
  const MetricInfo& completeness = *find_metric("map_completeness");  // higher is better
  EXPECT_EQ(compare_metric(completeness, 0.90, 0.95, t).verdict, Verdict::kRegressed);
  EXPECT_EQ(compare_metric(completeness, 0.99, 0.95, t).verdict, Verdict::kImproved);
  const MetricInfo& fps = *find_metric("frames_per_second");
  EXPECT_EQ(compare_metric(fps, 10, 30, {0, 0.3}).verdict, Verdict::kWarning);
  EXPECT_FALSE(is_failure(Verdict::kWarning));
  const MetricInfo& lost = *find_metric("frames_lost");
  EXPECT_EQ(compare_metric(lost, 1, 0, lost.tolerance).verdict, Verdict::kRegressed);
  EXPECT_EQ(compare_metric(lost, std::nullopt, 0, lost.tolerance).verdict, Verdict::kMissing);
  EXPECT_EQ(compare_metric(lost, 3, std::nullopt, lost.tolerance).verdict, Verdict::kNew);
}

TEST(Comparison, EveryMetricOfRunOrBaselineInReportOrder) {
  const RunMetrics run = {{"ate_rmse", 0.002}, {"run_seconds", 3}};
  const RunMetrics baseline = {{"ate_rmse", 0.002}, {"frames_lost", 0}};
  const auto rows = compare_metrics(run, &baseline, {}, true);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].metric->key, "ate_rmse");
  EXPECT_EQ(rows[1].metric->key, "frames_lost");
  EXPECT_EQ(rows[1].verdict, Verdict::kMissing);
  EXPECT_EQ(rows[2].verdict, Verdict::kNew);
  EXPECT_EQ(format_delta(compare_metric(*find_metric("ate_rmse"), 0.0021, 0.002, {})),
            "+0.00010 m (+5.0%)");
}

// Timing from other hardware says nothing about this build: not judged, while accuracy still is.
TEST(Comparison, TimingIsJudgedOnlyAgainstABaselineFromTheSameMachine) {
  const RunMetrics run = {{"ate_rmse", 0.009}, {"frames_per_second", 28.7}};
  const RunMetrics baseline = {{"ate_rmse", 0.004}, {"frames_per_second", 52.5}};
  const auto same = compare_metrics(run, &baseline, {}, true);
  ASSERT_EQ(same.size(), 2u);
  EXPECT_EQ(same[0].verdict, Verdict::kRegressed);
  EXPECT_EQ(same[1].verdict, Verdict::kWarning);
  const auto other = compare_metrics(run, &baseline, {}, false);
  ASSERT_EQ(other.size(), 2u);
  EXPECT_EQ(other[0].verdict, Verdict::kRegressed);
  EXPECT_EQ(other[1].verdict, Verdict::kOtherMachine);
  EXPECT_FALSE(is_failure(Verdict::kOtherMachine));
  // A timing with no baseline value stays new either way.
  const RunMetrics no_timing = {{"ate_rmse", 0.004}};
  EXPECT_EQ(compare_metrics(run, &no_timing, {}, false)[1].verdict, Verdict::kNew);
}

TEST(Comparison, SameMachineIsTheSameCpuAndCoresWhateverTheKernel) {
  const std::string here = "AMD EPYC, 2 cores, Linux 6.18.44-fc-v1045";
  EXPECT_TRUE(same_machine(here, "AMD EPYC, 2 cores, Linux 6.18.44-fc-v1252"));
  EXPECT_FALSE(same_machine(here, "AMD EPYC, 4 cores, Linux 6.18.44-fc-v1045"));
  EXPECT_FALSE(same_machine(here, "Intel(R) Xeon(R) Processor, 2 cores, Linux 6.18.44-fc-v769"));
  EXPECT_FALSE(same_machine("", here));  // a baseline without a machine: unknown
  EXPECT_TRUE(same_machine(machine_description(), machine_description()));
}

// A run folder left by an interrupted run (run.json not complete) gives no metrics: the
// runner reports the entry as failed instead of comparing half a run.
TEST(Comparison, RunMetricsRefuseAFolderWhoseRunIsNotComplete) {
  const std::filesystem::path dir = test::temp_dir("regress_metrics");
  std::ofstream(dir / "timing.json") << R"({"frames_per_second": 30})";
  EXPECT_NO_THROW(read_run_metrics(dir));
  std::ofstream(dir / "run.json") << R"({"status": "interrupted", "signal": 2})";
  EXPECT_THROW(read_run_metrics(dir), InputError);
  std::ofstream(dir / "run.json") << R"({"status": "complete"})";
  EXPECT_NO_THROW(read_run_metrics(dir));
}

}  // namespace
}  // namespace slamkit::regress
