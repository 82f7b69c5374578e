#include "io/trajectory_io.h"

#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

using test::write_text;

Trajectory random_trajectory(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-3, 3);
  Trajectory t;
  double stamp = 1305031453.359684;
  for (int i = 0; i < n; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
    T.translation() = Eigen::Vector3d(uni(rng), uni(rng), uni(rng));
    t.push_back(stamp, T);
    stamp += 0.0333337 + 1e-7 * i;
  }
  return t;
}

TEST(TrajectoryIo, RoundTripsExactly) {
  const fs::path dir = test::temp_dir("traj");
  const Trajectory original = random_trajectory(200, 11);
  write_tum_trajectory(dir / "t.txt", original, "written by a test");
  const TrajectoryFile read = read_tum_trajectory(dir / "t.txt");
  ASSERT_EQ(read.trajectory.size(), original.size());
  EXPECT_TRUE(read.warnings.empty());
  for (size_t i = 0; i < original.size(); ++i) {
    EXPECT_EQ(read.trajectory[i].stamp, original[i].stamp);
    EXPECT_LT((read.trajectory[i].T_w_c.matrix() - original[i].T_w_c.matrix()).norm(), 1e-9);
  }
}

TEST(TrajectoryIo, AcceptsTabsCommasCrlfCommentsAndNormalisesQuaternions) {
  const fs::path dir = test::temp_dir("traj");
  const fs::path path = write_text(dir, "t.txt",
                                   "# comment\r\n\r\n"
                                   "1.0\t1 2 3 0 0 0 2\r\n"
                                   "2.0,1,2,3,0,0,0,1\r\n");
  const TrajectoryFile read = read_tum_trajectory(path);
  ASSERT_EQ(read.trajectory.size(), 2u);
  EXPECT_TRUE(read.trajectory[0].T_w_c.rotation().isIdentity(1e-12));
  EXPECT_EQ(read.trajectory[1].T_w_c.translation(), Eigen::Vector3d(1, 2, 3));
}

TEST(TrajectoryIo, SkipsZeroQuaternionsAndNonFiniteLinesWithWarnings) {
  const fs::path dir = test::temp_dir("traj");
  const fs::path path = write_text(dir, "t.txt",
                                   "1 0 0 0 0 0 0 1\n"
                                   "2 0 0 0 0 0 0 0\n"
                                   "3 nan 0 0 0 0 0 1\n"
                                   "4 0 0 0 0 0 0 1\n");
  const TrajectoryFile read = read_tum_trajectory(path);
  EXPECT_EQ(read.trajectory.size(), 2u);
  EXPECT_EQ(read.zero_quaternions_skipped, 1);
  EXPECT_EQ(read.non_finite_lines_skipped, 1);
  ASSERT_EQ(read.warnings.size(), 2u);
  EXPECT_NE(read.warnings[0].find("t.txt:2"), std::string::npos);
  EXPECT_NE(read.warnings[1].find("t.txt:3"), std::string::npos);
}

TEST(TrajectoryIo, SortsUnsortedFilesWithAWarning) {
  const fs::path dir = test::temp_dir("traj");
  const fs::path path = write_text(dir, "t.txt", "2 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n");
  const TrajectoryFile read = read_tum_trajectory(path);
  EXPECT_TRUE(read.was_unsorted);
  EXPECT_EQ(read.trajectory[0].stamp, 1.0);
  EXPECT_EQ(read.trajectory[0].T_w_c.translation().x(), 1.0);
}

TEST(TrajectoryIo, KeepsTheLastLineOfARepeatedTimestampLikeTheBenchmark) {
  const fs::path dir = test::temp_dir("traj");
  const fs::path path =
      write_text(dir, "dup.txt", "1 0 0 0 0 0 0 1\n1 5 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n");
  const TrajectoryFile read = read_tum_trajectory(path);
  ASSERT_EQ(read.trajectory.size(), 2u);
  EXPECT_EQ(read.trajectory[0].T_w_c.translation().x(), 5.0);
  EXPECT_EQ(read.duplicate_stamps_dropped, 1);
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_NE(read.warnings[0].find("dup.txt:1: duplicate timestamp, line replaced by line 2"),
            std::string::npos);
}

void expect_error(const fs::path& path, const std::string& fragment) {
  try {
    read_tum_trajectory(path);
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(TrajectoryIo, RejectsMalformedFilesNamingFileAndLine) {
  const fs::path dir = test::temp_dir("traj");
  expect_error(write_text(dir, "seven.txt", "1 0 0 0 0 0 1\n"), "seven.txt:1: expected 8 fields");
  expect_error(write_text(dir, "nine.txt", "# h\n1 0 0 0 0 0 0 1 5\n"),
               "nine.txt:2: expected 8 fields");
  expect_error(write_text(dir, "word.txt", "1 0 0 x 0 0 0 1\n"),
               "word.txt:1: field 4 is not a number");
  expect_error(write_text(dir, "empty.txt", "# nothing\n"), "empty.txt: no valid pose");
  expect_error(dir / "missing.txt", "missing.txt: file not found");
}

TEST(TrajectoryIo, EvoKeepsTheFirstLineOfARepeatedTimestamp) {
  const fs::path dir = test::temp_dir("traj");
  const fs::path path =
      write_text(dir, "dup.txt", "1 0 0 0 0 0 0 1\n1 5 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n");
  const TrajectoryFile read =
      read_tum_trajectory(path, {TimeUnit::kSeconds, DuplicateStamps::kKeepFirst});
  ASSERT_EQ(read.trajectory.size(), 2u);
  EXPECT_EQ(read.trajectory[0].T_w_c.translation().x(), 0.0);
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_NE(read.warnings[0].find("dup.txt:2: duplicate timestamp, line dropped (keeping line 1)"),
            std::string::npos)
      << read.warnings[0];
}

TEST(TrajectoryIo, AllKeepsEveryLineOfARepeatedTimestampAsEvoDoes) {
  const fs::path dir = test::temp_dir("traj");
  const fs::path path =
      write_text(dir, "dup.txt", "1 0 0 0 0 0 0 1\n1 5 0 0 0 0 0 1\n2 0 0 0 0 0 0 1\n");
  const TrajectoryFile read =
      read_tum_trajectory(path, {TimeUnit::kSeconds, DuplicateStamps::kKeepAll});
  ASSERT_EQ(read.trajectory.size(), 3u);
  EXPECT_EQ(read.trajectory[1].T_w_c.translation().x(), 5.0);  // file order kept
  EXPECT_EQ(read.duplicate_stamps_dropped, 0);
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_NE(read.warnings[0].find("dup.txt:2: duplicate timestamp, line kept beside line 1"),
            std::string::npos)
      << read.warnings[0];
}

// Each of these was read without complaint (or echoed raw) before.
TEST(TrajectoryIo, HostileBytesAreErrorsNamingFileAndLineWithTheTextEscaped) {
  const fs::path dir = test::temp_dir("traj");
  const char nul[] = "1 0 0 0 0 0 0 1\n1305031102.311267\0garbage 0 0 0 0 0 0 1\n";
  expect_error(write_text(dir, "nul.txt", std::string(nul, sizeof nul - 1)),
               "nul.txt:2: field 1 is not a number: '1305031102.311267\\x00garbage'");
  expect_error(write_text(dir, "esc.txt", "1 0 0 \x1b[31mX\a 0 0 0 1\n"),
               "esc.txt:1: field 4 is not a number: '\\x1B[31mX\\x07'");
  expect_error(write_text(dir, "huge.txt", "1 0 0 0 0 0 0 1\n2 1e308 0 0 0 0 0 1\n"),
               "huge.txt:2: field 2 is 1e308, beyond +-1e100");
  try {
    read_tum_trajectory(write_text(dir, "bell.txt", "1 0 \a\x1b 0 0 0 0 1\n"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find_first_of("\a\x1b"), std::string::npos) << e.what();
  }
}

TEST(TrajectoryIo, SkipsAUtf8ByteOrderMark) {
  const fs::path dir = test::temp_dir("traj");
  const TrajectoryFile read = read_tum_trajectory(write_text(dir, "bom.txt",
                                                             "\xEF\xBB\xBF"
                                                             "1.5 1 2 3 0 0 0 1\n"));
  ASSERT_EQ(read.trajectory.size(), 1u);
  EXPECT_EQ(read.trajectory[0].stamp, 1.5);
}

// Integer nanosecond and microsecond stamps are converted exactly (to the nearest double of
// the decimal seconds, as a parser of "1305031102.311267" gives).
TEST(TrajectoryIo, ConvertsNanosecondAndMicrosecondStamps) {
  const fs::path dir = test::temp_dir("traj");
  const TrajectoryFile ns = read_tum_trajectory(
      write_text(dir, "ns.txt", "1305031102311267000 0 0 0 0 0 0 1\n"), {TimeUnit::kNanoseconds});
  EXPECT_EQ(ns.trajectory[0].stamp, 1305031102.311267);
  const TrajectoryFile us = read_tum_trajectory(
      write_text(dir, "us.txt", "1305031102311267 0 0 0 0 0 0 1\n"), {TimeUnit::kMicroseconds});
  EXPECT_EQ(us.trajectory[0].stamp, 1305031102.311267);
}

TEST(Printable, EscapesControlBytesAndC1ControlsAndCutsLongText) {
  EXPECT_EQ(printable("a\x1b[0m\tb"), "a\\x1B[0m\\x09b");
  EXPECT_EQ(printable("\xC2\x9B"
                      "2J \xC3\xA9"),
            "\\x9B2J \xC3\xA9");  // CSI escaped, e-acute kept
  EXPECT_EQ(printable("abcdef", 3), "abc...");
}

}  // namespace
}  // namespace slamkit
