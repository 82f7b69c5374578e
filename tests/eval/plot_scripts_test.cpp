// Where slamkit looks for its plot scripts: $SLAMKIT_EVAL_SCRIPTS alone when set; else beside
// an installed binary, then the source folder (the build tree's binary).
#include "eval/plot_scripts.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

TEST(PlotScripts, TheEnvironmentsFolderIsTheOnlyOneWhenSet) {
  const std::vector<fs::path> dirs = plot_script_dirs("/opt/scripts", "/usr/bin/slamkit");
  ASSERT_EQ(dirs.size(), 1u);
  EXPECT_EQ(dirs[0], "/opt/scripts");
  EXPECT_FALSE(find_in(dirs, "plot.py"));  // not there: no other folder is tried
}

TEST(PlotScripts, AnInstalledBinaryFindsTheScriptsUnderItsPrefixFirst) {
  const fs::path prefix = test::temp_dir("plot_scripts_prefix");
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share" / "slamkit" / "eval");
  std::ofstream(prefix / "share" / "slamkit" / "eval" / "plot.py") << "\n";
  const std::vector<fs::path> dirs = plot_script_dirs("", prefix / "bin" / "slamkit");
  ASSERT_EQ(dirs.size(), 2u);
  EXPECT_EQ(dirs[0], prefix / "share" / "slamkit" / "eval");
  EXPECT_EQ(dirs[1], fs::path(SLAMKIT_SOURCE_DIR) / "eval");
  EXPECT_EQ(find_in(dirs, "plot.py"), prefix / "share" / "slamkit" / "eval" / "plot.py");
}

TEST(PlotScripts, TheBuildTreesBinaryFindsThemInTheSourceFolder) {
  const fs::path build = test::temp_dir("plot_scripts_build");  // no share/ beside bin/
  const std::vector<fs::path> dirs = plot_script_dirs(nullptr, build / "bin" / "slamkit");
  EXPECT_EQ(find_in(dirs, "plot.py"), fs::path(SLAMKIT_SOURCE_DIR) / "eval" / "plot.py");
  EXPECT_FALSE(find_in(dirs, "no_such_script.py"));
}

}  // namespace
}  // namespace slamkit::eval
