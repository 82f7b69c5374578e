#include "io/trajectory_format.h"

#include <gtest/gtest.h>


#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

using test::write_text;

TrajectoryFormat detect(const std::string& text) {
  return detect_trajectory_format(write_text(test::temp_dir("format"), "f.txt", text));
}

TEST(TrajectoryFormat, DetectsEachFormatFromItsContent) {
  EXPECT_EQ(detect("# timestamp tx ty tz qx qy qz qw\n1.5 1 2 3 0 0 0 1\n"),
            TrajectoryFormat::kTum);
  EXPECT_EQ(detect("1305031453.359684,1,2,3,0,0,0,1\n"), TrajectoryFormat::kTum);
  EXPECT_EQ(detect("1.000000e+00 0 0 1 0 1 0 2 0 0 1 3\n"), TrajectoryFormat::kKitti);
  EXPECT_EQ(detect("1 0 0 1 0 1 0 2 0 0 1 3\n"), TrajectoryFormat::kKitti);
  EXPECT_EQ(detect("#timestamp [ns],p_x,p_y,p_z,q_w,q_x,q_y,q_z\n"), TrajectoryFormat::kEuroc);
  EXPECT_EQ(detect("\xEF\xBB\xBF#timestamp,x\n"), TrajectoryFormat::kEuroc);
  EXPECT_EQ(detect("1403636580838555648,1,2,3,1,0,0,0\n"), TrajectoryFormat::kEuroc);
  EXPECT_EQ(detect("5,1,2,3,1,0,0,0,9,9\n"), TrajectoryFormat::kEuroc);  // more than 8 fields
  // Other counts go to the TUM reader, whose error names the line.
  EXPECT_EQ(detect("1 2 3\n"), TrajectoryFormat::kTum);
  EXPECT_EQ(detect(""), TrajectoryFormat::kTum);
}

TEST(TrajectoryFormat, AmbiguousFilesAreRefusedNamingFileAndLine) {
  const fs::path dir = test::temp_dir("format");
  for (const char* text : {"# h\n5,1,2,3,1,0,0,0\n", "# h\n5,1,0,0,1,0,1,0,2,0,0,1\n"}) {
    try {
      detect_trajectory_format(write_text(dir, "small.csv", text));
      FAIL() << "no error for " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("small.csv:2: cannot tell the format"), std::string::npos) << what;
      EXPECT_NE(what.find("--format"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(TrajectoryFormat, ReadsInTheGivenOrDetectedFormat) {
  const fs::path dir = test::temp_dir("format");
  const fs::path euroc = write_text(dir, "e.csv", "200000000000,1,2,3,1,0,0,0\n");
  EXPECT_EQ(read_trajectory(euroc, std::nullopt, {}, std::nullopt).format, "euroc");
  // Given tum, the same line is 2e11 s (eval then says it looks like nanoseconds).
  const TrajectoryFile tum = read_trajectory(euroc, TrajectoryFormat::kTum, {}, std::nullopt);
  EXPECT_EQ(tum.format, "tum");
  EXPECT_EQ(tum.trajectory.stamp(0), 2e11);
  EXPECT_EQ(parse_trajectory_format("kitti"), TrajectoryFormat::kKitti);
  EXPECT_EQ(to_string(TrajectoryFormat::kEuroc), "euroc");
  EXPECT_THROW(parse_trajectory_format("csv"), std::invalid_argument);
}

}  // namespace
}  // namespace slamkit
