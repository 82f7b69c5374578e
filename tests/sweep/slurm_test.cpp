// The Slurm side without a cluster: --array values, the parsers over text that squeue, sacct and
// scontrol printed on the loopback cluster of scripts/slurm_loopback.sh (Slurm 22.05), and how
// a job's category follows from its run folder and Slurm's state.
#include "eval/sweep/slurm.h"

#include <gtest/gtest.h>

#include "eval/sweep/status.h"

namespace slamkit::sweep {
namespace {

TEST(Slurm, ArraySpecsRoundTrip) {
  EXPECT_EQ(array_spec({0, 1, 2, 3}, 2), "0-3%2");
  EXPECT_EQ(array_spec({9, 7, 8, 5, 0, 1, 2, 3, 5}, 0), "0-3,5,7-9");
  EXPECT_EQ(array_spec({4}, 32), "4%32");
  EXPECT_EQ(array_indices("0-3,5,7-9%4"), (std::vector<int>{0, 1, 2, 3, 5, 7, 8, 9}));
  EXPECT_EQ(array_indices("6"), std::vector<int>{6});
}

TEST(Slurm, ParsesSqueue) {
  // squeue -h -r --me -o '%F|%K|%T' with array 14 queued and another user's-style plain job.
  const ArrayStates s = parse_squeue(
      "14|0|RUNNING\n14|1|RUNNING\n14|2|PENDING\n14|3|PENDING\n"
      "20|N/A|RUNNING\n");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s.at("14").at(0), "RUNNING");
  EXPECT_EQ(s.at("14").at(3), "PENDING");
}

TEST(Slurm, ParsesSacct) {
  // sacct -n -P -X -j 10 -o JobID,State after task 0 was cancelled while running.
  const ArrayStates s =
      parse_sacct("10_0|CANCELLED by 0\n10_1|COMPLETED\n10_2|RUNNING\n10_[3-5%2]|PENDING\n");
  ASSERT_EQ(s.at("10").size(), 3u);
  EXPECT_EQ(s.at("10").at(0), "CANCELLED");
  EXPECT_EQ(s.at("10").at(1), "COMPLETED");
}

TEST(Slurm, ParsesScontrol) {
  const ArrayStates s = parse_scontrol(
      "JobId=17 ArrayJobId=14 ArrayTaskId=2 ArrayTaskThrottle=2 JobName=job.sh UserId=root(0) "
      "JobState=COMPLETED Reason=None Dependency=(null)\n"
      "JobId=15 ArrayJobId=14 ArrayTaskId=0 ArrayTaskThrottle=2 JobName=job.sh "
      "JobState=TIMEOUT Reason=TimeLimit\n"
      "JobId=14 ArrayJobId=14 ArrayTaskId=3-5%2 JobState=PENDING Reason=JobArrayTaskLimit\n");
  ASSERT_EQ(s.at("14").size(), 2u);
  EXPECT_EQ(s.at("14").at(2), "COMPLETED");
  EXPECT_EQ(s.at("14").at(0), "TIMEOUT");
}

TEST(SweepStatus, CategoryFromFolderAndSlurm) {
  EXPECT_EQ(classify(true, "complete", "CANCELLED"), TaskCategory::kDone);
  EXPECT_EQ(classify(false, "", "PENDING"), TaskCategory::kPending);
  EXPECT_EQ(classify(false, "running", "RUNNING"), TaskCategory::kRunning);
  EXPECT_EQ(classify(false, "interrupted", "CANCELLED"), TaskCategory::kFailed);
  EXPECT_EQ(classify(false, "", "TIMEOUT"), TaskCategory::kFailed);
  EXPECT_EQ(classify(false, "", "NODE_FAIL"), TaskCategory::kFailed);
  // Slurm finished it but the run left no finished marker.
  EXPECT_EQ(classify(false, "started", "COMPLETED"), TaskCategory::kFailed);
  // Without a word from Slurm: a run on this machine, or nothing at all.
  EXPECT_EQ(classify(false, "running", ""), TaskCategory::kRunning);
  EXPECT_EQ(classify(false, "interrupted", ""), TaskCategory::kFailed);
  EXPECT_EQ(classify(false, "", ""), TaskCategory::kMissing);
}

}  // namespace
}  // namespace slamkit::sweep
