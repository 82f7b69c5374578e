#include "io/euroc_csv.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

using test::write_text;

const std::string kHeader = "#timestamp [ns],p_x,p_y,p_z,q_w,q_x,q_y,q_z\n";

void expect_error(const fs::path& path, const std::string& fragment) {
  try {
    read_euroc_csv(path);
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// A double holds an epoch stamp to about 0.24 us, so the recorded nanoseconds are not kept digit
// for digit: the writer puts the nanosecond nearest to each stamp read, which reads back to the
// same stamp.
TEST(EurocCsv, AFileWrittenFromWhatWasReadReadsBackToTheSameStampsAndPoses) {
  const fs::path dir = test::temp_dir("euroc_write");
  const TrajectoryFile read = read_euroc_csv(write_text(
      dir, "in.csv",
      kHeader + "1403636580838555648,1,2,3,0.5,0.5,0.5,0.5\n"
                "1403636580843555328,4.25,5,6,0,0,0,1\n"
                "1403636580848555520,-0.001,0,1e-3,0.5,-0.5,0.5,-0.5\n"));
  write_euroc_csv(dir / "sub" / "out.csv", read.trajectory);
  const std::string text = test::read_text(dir / "sub" / "out.csv");
  EXPECT_EQ(text.substr(0, text.find('\n', text.find('\n') + 1) + 1),
            "#timestamp [ns],p_RS_R_x [m],p_RS_R_y [m],p_RS_R_z [m],q_RS_w [],q_RS_x [],"
            "q_RS_y [],q_RS_z []\n"
            "1403636580838555574,1,2,3,0.5,0.5,0.5,0.5\n");  // 74 ns from the file's, one double
  const TrajectoryFile back = read_euroc_csv(dir / "sub" / "out.csv");
  ASSERT_EQ(back.trajectory.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.trajectory.stamp(i), read.trajectory.stamp(i));
    EXPECT_EQ(back.trajectory.position(i), read.trajectory.position(i));
    EXPECT_EQ(back.trajectory.orientation(i).coeffs(), read.trajectory.orientation(i).coeffs());
  }
}

TEST(EurocCsv, ReadsKnownPosesWithWFirstQuaternionsAndNanosecondStamps) {
  const fs::path dir = test::temp_dir("euroc");
  // The groundtruth's 17 columns: velocity and biases after the quaternion are ignored.
  const TrajectoryFile f = read_euroc_csv(write_text(
      dir, "data.csv",
      "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], q_RS_y [], "
      "q_RS_z [], v_x, v_y, v_z, bw_x, bw_y, bw_z, ba_x, ba_y, ba_z\n"
      "1403636580838555648,1,2,3,0.5,0.5,0.5,0.5,9,9,9,9,9,9,9,9,9\n"
      "1403636580843555328, 4, 5, 6, 0, 0, 0, 1, 9, 9, 9, 9, 9, 9, 9, 9, 9\n"));
  ASSERT_EQ(f.trajectory.size(), 2u);
  EXPECT_EQ(f.format, "euroc");
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_EQ(f.trajectory.stamp(0), 1403636580.0 + 0.838555648);  // as --time-unit ns converts
  EXPECT_EQ(f.trajectory.position(0), Eigen::Vector3d(1, 2, 3));
  // w first: (w, x, y, z) = (0.5, 0.5, 0.5, 0.5) is 120 deg about (1,1,1): x -> y.
  const Eigen::Quaterniond& q = f.trajectory.orientation(0);
  EXPECT_EQ(q.w(), 0.5);
  EXPECT_EQ(q.x(), 0.5);
  EXPECT_LT((f.trajectory.pose(0).linear() * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY())
                .norm(),
            1e-15);
  // (0, 0, 0, 1) is 180 deg about z (read x-first it would be the identity).
  EXPECT_EQ(std::abs(f.trajectory.orientation(1).z()), 1.0);
  EXPECT_LT((f.trajectory.pose(1).linear() * Eigen::Vector3d::UnitX() + Eigen::Vector3d::UnitX())
                .norm(),
            1e-15);
}

TEST(EurocCsv, HostileFilesNameFileAndLine) {
  const fs::path dir = test::temp_dir("euroc");
  const std::string good = "1000000000,1,2,3,1,0,0,0\n";
  expect_error(write_text(dir, "short.csv", kHeader + good + "2000000000,1,2,3,1,0,0\n"),
               "short.csv:3: expected at least 8 fields");
  expect_error(write_text(dir, "float.csv", kHeader + "1.5e18,1,2,3,1,0,0,0\n"),
               "float.csv:2: field 1 is not an integer: '1.5e18'");
  expect_error(write_text(dir, "seconds.csv", kHeader + "1403636580.83,1,2,3,1,0,0,0\n"),
               "seconds.csv:2: field 1 is not an integer");
  expect_error(write_text(dir, "over.csv", kHeader + "9223372036854775808,1,2,3,1,0,0,0\n"),
               "over.csv:2: field 1 is beyond int64: '9223372036854775808'");
  expect_error(write_text(dir, "under.csv", kHeader + "-99999999999999999999,1,2,3,1,0,0,0\n"),
               "under.csv:2: field 1 is beyond int64");
  expect_error(write_text(dir, "word.csv", kHeader + "1000,1,2,x,1,0,0,0\n"),
               "word.csv:2: field 4 is not a number: 'x'");
  expect_error(write_text(dir, "huge.csv", kHeader + "1000,1,2,3,1e300,0,0,0\n"),
               "huge.csv:2: field 5 is 1e300, beyond +-1e100");
  expect_error(write_text(dir, "empty.csv", kHeader), "empty.csv: no valid pose");
}

TEST(EurocCsv, SkipsNonFiniteAndZeroQuaternionsAndHandlesUnsortedAndRepeatedStampsAsTum) {
  const fs::path dir = test::temp_dir("euroc");
  const fs::path path = write_text(dir, "e.csv",
                                   kHeader + "3000000000,1,2,3,1,0,0,0\n" +
                                       "4000000000,nan,2,3,1,0,0,0\n" +
                                       "5000000000,1,2,3,0,0,0,0\n" +
                                       "1000000000,1,2,3,1,0,0,0\n" +
                                       "1000000000,7,2,3,1,0,0,0\n");
  const TrajectoryFile last = read_euroc_csv(path);
  ASSERT_EQ(last.trajectory.size(), 2u);
  EXPECT_EQ(last.non_finite_lines_skipped, 1);
  EXPECT_EQ(last.zero_quaternions_skipped, 1);
  EXPECT_TRUE(last.was_unsorted);
  EXPECT_EQ(last.duplicate_stamps_dropped, 1);
  EXPECT_EQ(last.trajectory.position(0).x(), 7.0);  // the last line of stamp 1 s
  EXPECT_NE(last.warnings[0].find("e.csv:3: non-finite value"), std::string::npos);
  EXPECT_NE(last.warnings[1].find("e.csv:4: zero quaternion"), std::string::npos);
  const TrajectoryFile first = read_euroc_csv(path, {TimeUnit::kSeconds, DuplicateStamps::kKeepFirst});
  EXPECT_EQ(first.trajectory.position(0).x(), 1.0);
}

}  // namespace
}  // namespace slamkit
