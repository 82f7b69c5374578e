#include "io/kitti_poses.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

using test::write_text;

const char* kIdentityAt123 = "1 0 0 1 0 1 0 2 0 0 1 3\n";
const char* kQuarterTurnZ = "0 -1 0 4 1 0 0 5 0 0 1 6\n";  // 90 deg about z

void expect_error(const fs::path& poses, const std::optional<fs::path>& times,
                  const std::string& fragment) {
  try {
    read_kitti_poses(poses, times);
    FAIL() << "no error for " << poses;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(KittiPoses, ReadsKnownPosesWithIndexStamps) {
  const fs::path dir = test::temp_dir("kitti");
  const TrajectoryFile f =
      read_kitti_poses(write_text(dir, "p.txt", std::string(kIdentityAt123) + kQuarterTurnZ),
                       std::nullopt);
  ASSERT_EQ(f.trajectory.size(), 2u);
  EXPECT_EQ(f.format, "kitti");
  EXPECT_TRUE(f.warnings.empty());
  EXPECT_EQ(f.trajectory.stamp(0), 0.0);
  EXPECT_EQ(f.trajectory.stamp(1), 1.0);
  EXPECT_EQ(f.trajectory.position(0), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(f.trajectory.position(1), Eigen::Vector3d(4, 5, 6));
  EXPECT_TRUE(f.trajectory.pose(0).linear().isIdentity(0));
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_LT((f.trajectory.pose(1).linear() - R).norm(), 1e-15);
  EXPECT_NEAR(std::abs(f.trajectory.orientation(1).w()), std::sqrt(0.5), 1e-15);
}

TEST(KittiPoses, TakesStampsFromTimesFile) {
  const fs::path dir = test::temp_dir("kitti");
  const fs::path poses = write_text(dir, "p.txt", std::string(kIdentityAt123) + kQuarterTurnZ);
  const fs::path times = write_text(dir, "times.txt", "0.000000e+00\n1.036742e-01\n");
  const TrajectoryFile f = read_kitti_poses(poses, times);
  ASSERT_EQ(f.trajectory.size(), 2u);
  EXPECT_EQ(f.trajectory.stamp(0), 0.0);
  EXPECT_EQ(f.trajectory.stamp(1), 1.036742e-01);
}

// A pose as KITTI's own files print it: 7 significant digits, so R^T R - I is about 1e-7.
const char* kRoundedPose =
    "9.999978e-01 5.272628e-04 -2.066935e-03 -4.690294e-02 -5.296506e-04 9.999992e-01 "
    "-1.154865e-03 -2.839928e-02 2.066324e-03 1.155958e-03 9.999971e-01 8.586941e-01\n";

Eigen::Matrix3d rounded_rotation() {
  Eigen::Matrix3d R;
  R << 9.999978e-01, 5.272628e-04, -2.066935e-03, -5.296506e-04, 9.999992e-01, -1.154865e-03,
      2.066324e-03, 1.155958e-03, 9.999971e-01;
  return R;
}

TEST(KittiPoses, KeepsTheRotationMatricesAsWritten) {
  const fs::path dir = test::temp_dir("kitti");
  const TrajectoryFile f = read_kitti_poses(
      write_text(dir, "p.txt", std::string(kIdentityAt123) + kRoundedPose), std::nullopt);
  ASSERT_TRUE(f.trajectory.keeps_rotations_as_written());
  EXPECT_EQ(f.trajectory.pose(1).linear(), rounded_rotation());
  // Its unit quaternion is the nearest rotation, which differs from the matrix as written.
  const Eigen::Matrix3d from_quaternion = f.trajectory.orientation(1).toRotationMatrix();
  EXPECT_GT((from_quaternion - rounded_rotation()).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT((from_quaternion - rounded_rotation()).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(KittiPoses, AWrittenFileAndItsTimesReadBackAsTheyWere) {
  const fs::path dir = test::temp_dir("kitti_write");
  const std::string rows = std::string(kIdentityAt123) + kQuarterTurnZ + kRoundedPose;
  const TrajectoryFile read = read_kitti_poses(
      write_text(dir, "p.txt", rows), write_text(dir, "times.txt", "0.0\n0.1036742\n0.2\n"));
  // The times file in a folder of its own, which does not exist yet.
  write_kitti_poses(dir / "out" / "p.txt", read.trajectory, dir / "out" / "t" / "times.txt");
  // Every matrix as it was read (in shortest exact form: 9.999978e-01 is 0.9999978).
  const std::string written = test::read_text(dir / "out" / "p.txt");
  EXPECT_EQ(written.substr(0, std::strlen(kIdentityAt123) + std::strlen(kQuarterTurnZ)),
            std::string(kIdentityAt123) + kQuarterTurnZ);
  EXPECT_EQ(test::read_text(dir / "out" / "t" / "times.txt"), "0\n0.1036742\n0.2\n");
  const TrajectoryFile back =
      read_kitti_poses(dir / "out" / "p.txt", dir / "out" / "t" / "times.txt");
  ASSERT_EQ(back.trajectory.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.trajectory.stamp(i), read.trajectory.stamp(i));
    EXPECT_EQ(back.trajectory.pose(i).matrix(), read.trajectory.pose(i).matrix()) << i;
  }
  EXPECT_EQ(back.trajectory.pose(2).linear(), rounded_rotation());
}

TEST(KittiPoses, HostileFilesNameFileAndLine) {
  const fs::path dir = test::temp_dir("kitti");
  const std::string good = kIdentityAt123;
  expect_error(write_text(dir, "short.txt", good + "1 0 0 1 0 1 0 2 0 0 1\n"), std::nullopt,
               "short.txt:2: expected 12 fields");
  expect_error(write_text(dir, "long.txt", "1 0 0 1 0 1 0 2 0 0 1 3 4\n"), std::nullopt,
               "long.txt:1: expected 12 fields");
  expect_error(write_text(dir, "word.txt", "1 0 0 x 0 1 0 2 0 0 1 3\n"), std::nullopt,
               "word.txt:1: field 4 is not a number: 'x'");
  expect_error(write_text(dir, "huge.txt", "1 0 0 1e200 0 1 0 2 0 0 1 3\n"), std::nullopt,
               "huge.txt:1: field 4 is 1e200, beyond +-1e100");
  expect_error(write_text(dir, "skew.txt", good + "1 0.1 0 1 0 1 0 2 0 0 1 3\n"), std::nullopt,
               "skew.txt:2: fields 1-3, 5-7, 9-11 are not a rotation matrix");
  expect_error(write_text(dir, "zero.txt", "0 0 0 1 0 0 0 2 0 0 0 3\n"), std::nullopt,
               "zero.txt:1: fields 1-3, 5-7, 9-11 are not a rotation matrix");
  expect_error(write_text(dir, "mirror.txt", "-1 0 0 1 0 1 0 2 0 0 1 3\n"), std::nullopt,
               "mirror.txt:1: fields 1-3, 5-7, 9-11 are a reflection");
  expect_error(write_text(dir, "empty.txt", "\n"), std::nullopt, "empty.txt: no valid pose");

  const fs::path three = write_text(dir, "three.txt", good + good + good);
  expect_error(three, write_text(dir, "t2.txt", "0\n1\n"), "three.txt:3: pose 3 has no stamp");
  expect_error(three, write_text(dir, "t4.txt", "0\n1\n2\n3\n"),
               "t4.txt:4: stamp 4 has no pose");
  expect_error(three, write_text(dir, "tw.txt", "0\nx\n2\n"),
               "tw.txt:2: field 1 is not a number: 'x'");
  expect_error(three, write_text(dir, "t2f.txt", "0\n1 2\n2\n"),
               "t2f.txt:2: expected 1 field");
  expect_error(three, dir / "missing.txt", "missing.txt: file not found");
}

TEST(KittiPoses, SkipsNonFiniteAndHandlesUnsortedAndRepeatedStampsAsTum) {
  const fs::path dir = test::temp_dir("kitti");
  const std::string good = kIdentityAt123;
  const fs::path poses =
      write_text(dir, "p.txt", good + "1 0 0 nan 0 1 0 2 0 0 1 3\n" + good + kRoundedPose);
  const TrajectoryFile f = read_kitti_poses(poses, write_text(dir, "t.txt", "2\n3\n1\n1\n"));
  // Line 2 skipped, lines 3 and 4 share stamp 1 (the last kept), sorted before line 1.
  ASSERT_EQ(f.trajectory.size(), 2u);
  EXPECT_EQ(f.non_finite_lines_skipped, 1);
  EXPECT_TRUE(f.was_unsorted);
  EXPECT_EQ(f.duplicate_stamps_dropped, 1);
  EXPECT_EQ(f.trajectory.stamp(0), 1.0);
  EXPECT_EQ(f.trajectory.stamp(1), 2.0);
  // The matrices as written follow their lines through sorting and the repeated stamp.
  EXPECT_EQ(f.trajectory.pose(0).linear(), rounded_rotation());
  EXPECT_TRUE(f.trajectory.pose(1).linear().isIdentity(0));
  ASSERT_EQ(f.warnings.size(), 3u);
  EXPECT_EQ(f.warnings[0].find(poses.string() + ":2: non-finite value"), 0u) << f.warnings[0];
  EXPECT_NE(f.warnings[2].find("p.txt:3: duplicate timestamp, line replaced by line 4"),
            std::string::npos)
      << f.warnings[2];
  // A NaN stamp skips its pose as well.
  EXPECT_EQ(read_kitti_poses(poses, write_text(dir, "tn.txt", "nan\n3\n1\n0\n"))
                .non_finite_lines_skipped,
            2);
}

}  // namespace
}  // namespace slamkit
