// run.json: written first as running and last as complete, and an interrupted run leaves a
// folder marked so, without half-written files, that readers refuse.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/error.h"
#include "eval/metrics/checksum.h"
#include "eval/metrics/metrics_json.h"
#include "eval/regression/metrics.h"
#include "pipeline/run_output.h"
#include "pipeline/run_pipeline.h"
#include "pipeline_test_support.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& path) {
  return nlohmann::json::parse(test::file_text(path), nullptr, false);
}

std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().extension() == ".tmp") found.push_back(entry.path().string());
  return found;
}

TEST(RunStatus, RunJsonIsRunningWhileTheRunGoesAndCompleteAfterEveryOtherFile) {
  const fs::path dir = test::temp_dir("run_status") / "run";
  const TumSequence seq = TumSequence::open(test::synthetic_sequence(synth::Preset::kDesk, 10));
  const Settings settings = front_end_only(Settings{});
  const RunStart started = begin_run_folder(dir, settings);
  EXPECT_EQ(read_json(dir / "run.json")["status"], "running");
  const RunResult result = track_sequence(seq, settings);
  write_run_outputs(dir, "desk", seq.camera(), settings, result);
  EXPECT_THROW(eval::require_complete_run(dir), InputError);
  write_run_status(started, result.seconds);

  const nlohmann::json status = read_json(dir / "run.json");
  EXPECT_EQ(status["status"], "complete");
  EXPECT_EQ(status["settings_hash"], eval::fnv1a64_file(dir / "settings.yaml"));
  EXPECT_TRUE(status["started"].is_string() && status["ended"].is_string());
  EXPECT_EQ(status["seconds"]["total"], result.seconds.total);
  const auto last = fs::last_write_time(dir / "run.json");
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_LE(fs::last_write_time(entry.path()), last) << entry.path();
  EXPECT_TRUE(temporaries(dir).empty());
  EXPECT_NO_THROW(eval::require_complete_run(dir));
}

// The Python module's way: signals stay the caller's, and a RunInterrupted thrown through the
// work marks the folder as the CLI's handler does.
TEST(RunStatus, RunInterruptedThrownThroughTheWorkMarksTheFolderAndLeavesSignalsAlone) {
  const fs::path dir = test::temp_dir("run_status_raise") / "run";
  struct sigaction before {};
  sigaction(SIGINT, nullptr, &before);
  const RunStart started = begin_run_folder(dir, Settings{}, OnSignal::kRaise);
  EXPECT_FALSE(started.handles_signals);
  EXPECT_THROW(fill_run_folder(started, []() -> StageTimes { throw RunInterrupted(SIGINT); }),
               RunInterrupted);
  struct sigaction after {};
  sigaction(SIGINT, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler);
  const nlohmann::json status = read_json(dir / "run.json");
  EXPECT_EQ(status["status"], "interrupted");
  EXPECT_EQ(status["signal"], SIGINT);
  EXPECT_EQ(status["settings_hash"], started.settings_hash);
  EXPECT_THROW(eval::require_complete_run(dir), InputError);
  EXPECT_TRUE(temporaries(dir).empty());
}

// A view of `sequence` in `view`: its lists and files copied, its images linked, except
// `blocked_image` (a path relative to the folder), which is a named pipe: reading that frame
// waits for a writer, so a run stops there for as long as the test wants.
void link_sequence_with_blocking_frame(const fs::path& sequence, const fs::path& view,
                                       const fs::path& blocked_image) {
  fs::create_directories(view);
  for (const auto& entry : fs::directory_iterator(sequence)) {
    const fs::path target = view / entry.path().filename();
    if (entry.is_regular_file()) {
      fs::copy_file(entry.path(), target);
    } else if (entry.is_directory()) {
      fs::create_directories(target);
      for (const auto& image : fs::directory_iterator(entry.path()))
        if (entry.path().filename() / image.path().filename() != blocked_image)
          fs::create_symlink(image.path(), target / image.path().filename());
    }
  }
  ASSERT_EQ(mkfifo((view / blocked_image).c_str(), 0600), 0) << (view / blocked_image);
}

// Opens the pipe for writing once the run has opened it for reading (so the run is blocked
// in that frame); fails if the run ends first.
int open_when_the_run_reads(const fs::path& pipe, pid_t run) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::minutes(5)) {
    const int fd = open(pipe.c_str(), O_WRONLY | O_NONBLOCK);  // ENXIO while no reader
    if (fd >= 0) return fd;
    if (errno != ENXIO) break;
    int status = 0;
    if (waitpid(run, &status, WNOHANG) == run) break;  // ended before the frame
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return -1;
}

TEST(RunStatus, SigtermMidRunMarksTheFolderInterruptedAndLeavesNoTemporary) {
  const fs::path original = test::synthetic_sequence(synth::Preset::kDesk, 150);
  const fs::path sequence = test::temp_dir("run_status_sequence") / "desk";
  const fs::path blocked = TumSequence::open(original).files(100).rgb.file;
  ASSERT_NO_FATAL_FAILURE(link_sequence_with_blocking_frame(original, sequence, blocked));
  const fs::path dir = test::temp_dir("run_status") / "run";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(SLAMKIT_BINARY, SLAMKIT_BINARY, "run", sequence.c_str(), "--out", dir.c_str(),
          "--threads", "1", nullptr);
    _exit(127);
  }
  // Mid-run: the run waits in frame 100 of 150, so run.json says running.
  const int pipe = open_when_the_run_reads(sequence / blocked, child);
  ASSERT_GE(pipe, 0) << "the run ended before reading frame 100";
  ASSERT_EQ(read_json(dir / "run.json")["status"], "running");
  kill(child, SIGTERM);
  int wait_status = 0;
  ASSERT_EQ(waitpid(child, &wait_status, 0), child);
  close(pipe);
  ASSERT_TRUE(WIFEXITED(wait_status));
  EXPECT_EQ(WEXITSTATUS(wait_status), 128 + SIGTERM);

  const nlohmann::json status = read_json(dir / "run.json");
  EXPECT_EQ(status["status"], "interrupted");
  EXPECT_EQ(status["signal"], SIGTERM);
  EXPECT_TRUE(temporaries(dir).empty());
  try {
    eval::require_complete_run(dir);
    FAIL() << "an interrupted run was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.json: the run is not complete (status "
                                         "'interrupted')"),
              std::string::npos)
        << e.what();
  }

  // The readers refuse it: eval compare in one line naming run.json, regress's metrics reader.
  const test::SlamkitResult compare =
      test::run_slamkit_apart("eval compare " + dir.string() + " --out " + (dir / "cmp").string());
  EXPECT_EQ(compare.code, 2);
  EXPECT_EQ(compare.err, "slamkit: error: " + (dir / "run.json").string() +
                             ": the run is not complete (status 'interrupted'): it stopped on an "
                             "error, was interrupted or is still running; run it again\n");
  EXPECT_THROW(regress::read_run_metrics(dir), InputError);

  // Run again into the same folder, the frame readable: complete, and both readers take it.
  fs::remove(sequence / blocked);
  fs::create_symlink(original / blocked, sequence / blocked);
  std::string output;
  ASSERT_EQ(test::run_slamkit("run " + sequence.string() + " --out " + dir.string(), &output), 0)
      << output;
  EXPECT_EQ(read_json(dir / "run.json")["status"], "complete");
  EXPECT_TRUE(temporaries(dir).empty());
  EXPECT_EQ(test::run_slamkit("eval compare " + dir.string() + " --out " + (dir / "cmp").string(),
                              &output),
            0)
      << output;
  EXPECT_GT(regress::read_run_metrics(dir).count("ate_rmse"), 0u);
}

TEST(RunStatus, BadInputMidRunMarksTheFolderFailed) {
  const fs::path folder = test::temp_dir("run_status");  // emptied at each call: once
  const fs::path sequence = folder / "seq";
  fs::copy(test::synthetic_sequence(synth::Preset::kDesk, 10), sequence,
           fs::copy_options::recursive);
  const auto depth = *fs::directory_iterator(sequence / "depth");
  std::ofstream(depth.path(), std::ios::trunc) << "not a png";
  const fs::path dir = folder / "run";
  std::string output;
  EXPECT_EQ(test::run_slamkit("run " + sequence.string() + " --out " + dir.string(), &output), 2);
  const nlohmann::json status = read_json(dir / "run.json");
  EXPECT_EQ(status["status"], "failed");
  EXPECT_NE(status["error"].get<std::string>().find(depth.path().string()), std::string::npos);
  EXPECT_THROW(eval::require_complete_run(dir), InputError);
}

}  // namespace
}  // namespace slamkit
