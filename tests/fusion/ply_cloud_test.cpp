// PLY files of point clouds: written and read back exactly (binary) or to six digits (ASCII),
// checked by PCL's reader and by an independent one; bad files name their path.
#include "fusion/ply_cloud.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "ply_reader.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;
using test::parse_ply;
using test::random_cloud;

TEST(PlyCloud, BinaryRoundTripIsExactAndAsciiKeepsSixDigits) {
  const fs::path dir = test::temp_dir("ply_round_trip");
  const PlyCloud cloud = random_cloud(1000);
  write_ply_cloud(dir / "binary.ply", cloud, true);
  write_ply_cloud(dir / "ascii.ply", cloud, false);
  EXPECT_FALSE(fs::exists(temporary_path(dir / "binary.ply")));

  for (const PlyCloud& back :
       {read_ply_cloud(dir / "binary.ply"), parse_ply(dir / "binary.ply").cloud}) {
    ASSERT_EQ(back.points.size(), cloud.points.size());
    for (size_t i = 0; i < cloud.points.size(); ++i) {
      EXPECT_EQ(back.points[i], cloud.points[i]) << i;
      EXPECT_EQ(back.colours[i], cloud.colours[i]) << i;
    }
  }
  for (const PlyCloud& back :
       {read_ply_cloud(dir / "ascii.ply"), parse_ply(dir / "ascii.ply").cloud}) {
    ASSERT_EQ(back.points.size(), cloud.points.size());
    for (size_t i = 0; i < cloud.points.size(); ++i) {
      // PCL prints 6 significant digits: |x| < 4 m keeps 5e-6 m.
      EXPECT_LT((back.points[i] - cloud.points[i]).cwiseAbs().maxCoeff(), 5.1e-6f) << i;
      EXPECT_EQ(back.colours[i], cloud.colours[i]) << i;
    }
  }
  EXPECT_EQ(read_ply_points(dir / "binary.ply"), cloud.points);
}

TEST(PlyCloud, BadFilesAndCloudsAreInputErrorsNamingThePath) {
  const fs::path dir = test::temp_dir("ply_bad");
  const auto expect_error_naming = [](const fs::path& path, const auto& action) {
    try {
      action();
      ADD_FAILURE() << "expected InputError for " << path;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
  };
  expect_error_naming(dir / "missing.ply", [&] { read_ply_cloud(dir / "missing.ply"); });
  std::ofstream(dir / "text.ply") << "not a ply\n";
  expect_error_naming(dir / "text.ply", [&] { read_ply_cloud(dir / "text.ply"); });
  expect_error_naming(dir / "empty.ply", [&] { write_ply_cloud(dir / "empty.ply", {}); });
  PlyCloud uneven = random_cloud(3);
  uneven.colours.pop_back();
  expect_error_naming(dir / "uneven.ply", [&] { write_ply_cloud(dir / "uneven.ply", uneven); });
  std::ofstream(dir / "blocker") << "a file, not a folder";
  const fs::path unwritable = dir / "blocker" / "map.ply";
  expect_error_naming(unwritable, [&] { write_ply_cloud(unwritable, random_cloud(3)); });
}

}  // namespace
}  // namespace slamkit
