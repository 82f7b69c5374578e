// The command line's parsers end to end: a bad settings file or sequence list gives exit code 2
// and one line naming the file and line, before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

TEST(SettingsYaml, CliRejectsAnOutOfRangeSettingWithOneLineAndExitTwo) {
  const fs::path dir = test::temp_dir("settings");
  std::ofstream(dir / "bad.yaml") << "orb:\n  num_features: -5\n";
  std::string output;
  // The settings are read before the sequence is opened: no sequence needed.
  EXPECT_EQ(
      test::run_slamkit("track " + (dir / "none").string() + " --out " + (dir / "out").string() +
                            " --settings " + (dir / "bad.yaml").string(),
                        &output),
      2);
  EXPECT_NE(output.find("bad.yaml:2: orb.num_features: -5 is outside 1..100000"), std::string::npos)
      << output;
  EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  // --threads sets pipeline.threads: the same lower bound (a usage error, as CLI11 reports).
  EXPECT_NE(test::run_slamkit("track " + (dir / "none").string() + " --out " +
                                  (dir / "out").string() + " --threads -3",
                              &output),
            0);
  EXPECT_NE(output.find("--threads: Value -3 not in range 0 to"), std::string::npos) << output;
}

TEST(SequenceListCli, BadLineGivesOneLineNamingTheListAndExitTwo) {
  const fs::path dir = test::temp_dir("list_cli") / "rgbd_dataset_freiburg3_test";
  fs::create_directories(dir);
  std::ofstream(dir / "rgb.txt") << "1.00 rgb/1.png\nabc rgb/2.png\n";
  std::ofstream(dir / "depth.txt") << "1.01 depth/1.png\n1.11 depth/2.png\n";
  std::string output;
  EXPECT_EQ(test::run_slamkit("info " + dir.string(), &output), 2);
  EXPECT_NE(output.find("slamkit: error: "), std::string::npos);
  EXPECT_NE(output.find("rgb.txt:2:"), std::string::npos) << output;
  EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
}

}  // namespace
}  // namespace slamkit
