// The Slurm side without a cluster: --array values, the parsers over text that squeue, sacct and
// scontrol printed on the test cluster of scripts/slurm_cluster.sh (Slurm 22.05), and how a
// job's category follows from its run folder and Slurm's state.
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
  EXPECT_EQ(s.at("14").at(0).state, "RUNNING");
  EXPECT_EQ(s.at("14").at(3).state, "PENDING");
}

TEST(Slurm, ParsesSacct) {
  // sacct -n -P -X -j 10 -o JobID,State after task 0 was cancelled while running.
  const ArrayStates s =
      parse_sacct("10_0|CANCELLED by 0\n10_1|COMPLETED\n10_2|RUNNING\n10_[3-5%2]|PENDING\n");
  ASSERT_EQ(s.at("10").size(), 3u);
  EXPECT_EQ(s.at("10").at(0).state, "CANCELLED");
  EXPECT_EQ(s.at("10").at(1).state, "COMPLETED");
  EXPECT_EQ(s.at("10").at(0).restarts, 0);
}

TEST(Slurm, ParsesSacctAttemptsOfARequeuedTask) {
  // sacct -D after node2 died under task 1 (requeued, waiting to start again) and task 3 ran
  // again elsewhere after an earlier requeue.
  const ArrayStates s = parse_sacct(
      "1_0|COMPLETED\n1_1|NODE_FAIL\n1_2|COMPLETED\n1_1|PENDING\n1_3|NODE_FAIL\n1_3|REQUEUED\n"
      "1_3|RUNNING\n");
  EXPECT_EQ(s.at("1").at(0).state, "COMPLETED");
  EXPECT_EQ(s.at("1").at(0).restarts, 0);
  EXPECT_EQ(s.at("1").at(1).state, "PENDING");
  EXPECT_EQ(s.at("1").at(1).restarts, 1);
  EXPECT_EQ(s.at("1").at(3).state, "RUNNING");
  EXPECT_EQ(s.at("1").at(3).restarts, 2);
}

TEST(Slurm, ParsesScontrol) {
  const ArrayStates s = parse_scontrol(
      "JobId=17 ArrayJobId=14 ArrayTaskId=2 ArrayTaskThrottle=2 JobName=job.sh UserId=root(0) "
      "JobState=COMPLETED Reason=None Dependency=(null) Requeue=1 Restarts=0\n"
      "JobId=15 ArrayJobId=14 ArrayTaskId=0 ArrayTaskThrottle=2 JobName=job.sh "
      "JobState=TIMEOUT Reason=TimeLimit\n"
      "JobId=16 ArrayJobId=14 ArrayTaskId=1 JobState=PENDING Reason=BeginTime Requeue=1 "
      "Restarts=1 BatchFlag=1\n"
      "JobId=14 ArrayJobId=14 ArrayTaskId=3-5%2 JobState=PENDING Reason=JobArrayTaskLimit\n");
  ASSERT_EQ(s.at("14").size(), 3u);
  EXPECT_EQ(s.at("14").at(2).state, "COMPLETED");
  EXPECT_EQ(s.at("14").at(0).state, "TIMEOUT");
  EXPECT_EQ(s.at("14").at(1).state, "PENDING");
  EXPECT_EQ(s.at("14").at(1).restarts, 1);
}

TEST(SweepStatus, CategoryFromFolderAndSlurm) {
  const auto slurm = [](const char* state, int restarts = 0) {
    return TaskState{state, restarts, "1_0"};
  };
  EXPECT_EQ(classify(true, "complete", slurm("CANCELLED")), TaskCategory::kDone);
  EXPECT_EQ(classify(false, "", slurm("PENDING")), TaskCategory::kPending);
  EXPECT_EQ(classify(false, "running", slurm("RUNNING")), TaskCategory::kRunning);
  EXPECT_EQ(classify(false, "interrupted", slurm("CANCELLED")), TaskCategory::kFailed);
  EXPECT_EQ(classify(false, "", slurm("TIMEOUT")), TaskCategory::kFailed);
  EXPECT_EQ(classify(false, "", slurm("NODE_FAIL")), TaskCategory::kFailed);
  // Its node died and Slurm runs it again: waiting, or already running elsewhere.
  EXPECT_EQ(classify(false, "running", slurm("PENDING", 1)), TaskCategory::kRequeued);
  EXPECT_EQ(classify(false, "", slurm("REQUEUED", 1)), TaskCategory::kRequeued);
  EXPECT_EQ(classify(false, "running", slurm("RUNNING", 1)), TaskCategory::kRunning);
  // Slurm finished it but the run left no finished marker.
  EXPECT_EQ(classify(false, "started", slurm("COMPLETED")), TaskCategory::kFailed);
  // Without a word from Slurm: a run on this machine, or nothing at all.
  EXPECT_EQ(classify(false, "running", {}), TaskCategory::kRunning);
  EXPECT_EQ(classify(false, "interrupted", {}), TaskCategory::kFailed);
  EXPECT_EQ(classify(false, "", {}), TaskCategory::kMissing);
}

}  // namespace
}  // namespace slamkit::sweep
