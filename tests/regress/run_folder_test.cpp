// Publishing a run folder: one attempt wins, a dead attempt's folder never mixes into a run, a
// failed attempt is kept for its log until the job succeeds.
#include "eval/regression/run_folder.h"

#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <thread>

#include "support/test_data.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

bool never_the_same(const fs::path&) { return false; }

TEST(RunFolder, AnAttemptIsPublishedWholeAndItsFailedFolderGoes) {
  const fs::path dir = test::temp_dir("run_folder_publish");
  const fs::path run = dir / "seed1";
  write(failed_folder(run) / "run.log", "an earlier attempt failed\n");
  const fs::path attempt = attempt_folder(run);
  EXPECT_EQ(attempt.parent_path(), dir);
  write(attempt / "trajectory.txt", "poses\n");
  EXPECT_EQ(attempt_folders(run), std::vector<fs::path>{attempt});

  EXPECT_EQ(publish_attempt(attempt, run, never_the_same), Publication::kPublished);
  EXPECT_EQ(test::read_text(run / "trajectory.txt"), "poses\n");
  EXPECT_FALSE(fs::exists(attempt));
  EXPECT_FALSE(fs::exists(failed_folder(run)));
  EXPECT_TRUE(attempt_folders(run).empty());
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(RunFolder, TheSecondOfTwoAttemptsDiscardsItsCopy) {
  const fs::path dir = test::temp_dir("run_folder_second");
  const fs::path run = dir / "seed1";
  write(run / "trajectory.txt", "the first attempt's\n");
  const fs::path attempt = attempt_folder(run);
  write(attempt / "trajectory.txt", "the second attempt's\n");
  EXPECT_EQ(publish_attempt(attempt, run, [&](const fs::path& p) { return p == run; }),
            Publication::kPublishedByAnother);
  EXPECT_EQ(test::read_text(run / "trajectory.txt"), "the first attempt's\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(RunFolder, AnOutdatedRunFolderIsReplacedNotMixed) {
  const fs::path dir = test::temp_dir("run_folder_outdated");
  const fs::path run = dir / "seed1";
  write(run / "old_only.txt", "from other settings\n");
  const fs::path attempt = attempt_folder(run);
  write(attempt / "trajectory.txt", "new\n");
  EXPECT_EQ(publish_attempt(attempt, run, never_the_same), Publication::kPublished);
  EXPECT_FALSE(fs::exists(run / "old_only.txt"));
  EXPECT_EQ(test::read_text(run / "trajectory.txt"), "new\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(RunFolder, DeadAttemptsAreRemovedAndOnlyThem) {
  const fs::path dir = test::temp_dir("run_folder_stale");
  const fs::path run = dir / "seed1";
  write(fs::path(run.string() + ".attempt.node2.4711") / "tracking.csv", "half a fi");
  write(fs::path(run.string() + ".attempt.node3.99") / "run.json", "{\"status\": \"running\"}");
  write(dir / "seed10.attempt.node2.5" / "run.json", "another job's\n");  // not seed1's
  // A dead process of this host that had this process's pid: its files must not mix in either.
  write(attempt_folder(run) / "run.log", "a dead process's\n");
  EXPECT_EQ(attempt_folders(run).size(), 3u);
  EXPECT_EQ(remove_stale_attempts(run), 3);
  EXPECT_TRUE(attempt_folders(run).empty());
  EXPECT_TRUE(fs::exists(dir / "seed10.attempt.node2.5" / "run.json"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(RunFolder, AFailedAttemptIsKeptForItsLogReplacingTheLastOne) {
  const fs::path dir = test::temp_dir("run_folder_failed");
  const fs::path run = dir / "seed1";
  write(failed_folder(run) / "run.log", "first failure\n");
  const fs::path attempt = attempt_folder(run);
  write(attempt / "run.log", "second failure\n");
  keep_failed_attempt(attempt, run);
  EXPECT_EQ(test::read_text(failed_folder(run) / "run.log"), "second failure\n");
  EXPECT_FALSE(fs::exists(attempt));
  EXPECT_FALSE(fs::exists(run));
}

// Attempts racing for one run folder, as many as the machine runs at once: exactly one
// publishes, the folder holds that one's files only, and nothing else is left.
TEST(RunFolder, OfManyAttemptsPublishingAtOnceExactlyOneWins) {
  const fs::path dir = test::temp_dir("run_folder_race");
  const fs::path run = dir / "seed1";
  constexpr int kAttempts = 8;
  for (int round = 0; round < 20; ++round) {
    fs::remove_all(run);
    std::vector<fs::path> attempts;
    for (int i = 0; i < kAttempts; ++i) {
      // Named as attempts on other machines would be; each with files of its own.
      attempts.push_back(run.string() + ".attempt.node" + std::to_string(i) + ".1");
      for (const char* file : {"trajectory.txt", "map.ply", "metrics.json"})
        write(attempts.back() / file, "attempt " + std::to_string(i) + "\n");
    }
    std::atomic<int> published{0}, lost{0};
    std::vector<std::thread> threads;
    for (int i = 0; i < kAttempts; ++i)
      threads.emplace_back([&, i] {
        const Publication p =
            publish_attempt(attempts[i], run, [&](const fs::path& there) { return there == run; });
        (p == Publication::kPublished ? published : lost)++;
      });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(published.load(), 1) << "round " << round;
    EXPECT_EQ(lost.load(), kAttempts - 1);
    const std::string winner = test::read_text(run / "trajectory.txt");
    for (const char* file : {"map.ply", "metrics.json"})
      EXPECT_EQ(test::read_text(run / file), winner) << file;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  }
}

}  // namespace
}  // namespace slamkit::regress
