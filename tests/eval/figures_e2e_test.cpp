// Figures for papers, end to end: --plot-format (and --pdf, its older spelling), --dpi (on
// `eval` and on `run` and `track`), and `eval compare --trajectories`, which draws several runs
// of one groundtruth together.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

bool can_plot() { return std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") == 0; }

#define REQUIRE_MATPLOTLIB() \
  if (!can_plot()) GTEST_SKIP() << "/usr/bin/python3 cannot import matplotlib (scripts/setup.sh)"

// A helix of n poses at 30 Hz; `wobble` bends the positions so that the alignment leaves an error.
fs::path write_tum(const fs::path& path, size_t n, double wobble = 0.0) {
  std::ofstream out(path);
  out.precision(17);
  for (size_t k = 0; k < n; ++k) {
    const double s = 0.05 * double(k);
    out << 1000.0 + double(k) / 30.0 << " " << std::cos(s) + wobble * std::sin(3 * s) << " "
        << std::sin(s) << " " << 0.1 * s << " 0 0 " << std::sin(s / 2) << " " << std::cos(s / 2)
        << "\n";
  }
  return path;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::string head(const fs::path& file, size_t n) { return test::read_text(file).substr(0, n); }

// The PNG's width in pixels and its pHYs resolution in pixels per metre (0 without one).
std::pair<uint32_t, uint32_t> png_width_and_resolution(const fs::path& file) {
  const std::string bytes = test::read_text(file);
  const auto be32 = [&](size_t at) {
    uint32_t v = 0;
    for (size_t k = 0; k < 4; ++k) v = v << 8 | uint8_t(bytes.at(at + k));
    return v;
  };
  const size_t phys = bytes.find("pHYs");
  return {be32(16), phys == std::string::npos ? 0 : be32(phys + 4)};
}

TEST(Figures, PlotFormatWritesOnlyTheFormatsAskedForAndEachIsValid) {
  REQUIRE_MATPLOTLIB();
  const fs::path dir = test::temp_dir("figures");
  const fs::path gt = write_tum(dir / "gt.txt", 150);
  const fs::path est = write_tum(dir / "est.txt", 150, 0.01);
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) + " --plot " +
                                  quoted(dir / "p") + " --plot-format svg,pdf --quiet",
                              &log),
            0)
      << log;
  for (const char* name : {"ate_over_time", "trajectory_xy"}) {
    const std::string svg = head(dir / "p" / (std::string(name) + ".svg"), 200);
    EXPECT_TRUE(svg.rfind("<?xml", 0) == 0 || svg.rfind("<svg", 0) == 0) << name << ": " << svg;
    EXPECT_NE(svg.find("<svg"), std::string::npos) << name;
    EXPECT_EQ(head(dir / "p" / (std::string(name) + ".pdf"), 5), "%PDF-") << name;
    EXPECT_FALSE(fs::exists(dir / "p" / (std::string(name) + ".png"))) << name;
  }
  // Repeated instead of a list; --pdf adds PDF to the default PNG and SVG, as it always did.
  ASSERT_EQ(
      test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) + " --plot " +
                            quoted(dir / "r") + " --plot-format png --plot-format pdf --quiet",
                        &log),
      0)
      << log;
  EXPECT_TRUE(fs::exists(dir / "r" / "trajectory_xy.png"));
  EXPECT_TRUE(fs::exists(dir / "r" / "trajectory_xy.pdf"));
  EXPECT_FALSE(fs::exists(dir / "r" / "trajectory_xy.svg"));
  ASSERT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) + " --plot " +
                                  quoted(dir / "q") + " --pdf --quiet",
                              &log),
            0)
      << log;
  for (const char* ext : {".png", ".svg", ".pdf"})
    EXPECT_TRUE(fs::exists(dir / "q" / (std::string("trajectory_xy") + ext))) << ext;

  EXPECT_NE(
      test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) + " --plot-format eps", &log),
      0);
  EXPECT_NE(log.find("--plot-format"), std::string::npos) << log;
}

TEST(Figures, DpiSetsThePngResolutionAndItsPixelSize) {
  REQUIRE_MATPLOTLIB();
  const fs::path dir = test::temp_dir("figures");
  const fs::path gt = write_tum(dir / "gt.txt", 150);
  const fs::path est = write_tum(dir / "est.txt", 150, 0.01);
  std::string log;
  for (const char* dpi : {"100", "300"})
    ASSERT_EQ(
        test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) + " --plot " +
                              quoted(dir / dpi) + " --plot-format png --dpi " + dpi + " --quiet",
                          &log),
        0)
        << log;
  const auto [width_100, resolution_100] =
      png_width_and_resolution(dir / "100" / "ate_over_time.png");
  const auto [width_300, resolution_300] =
      png_width_and_resolution(dir / "300" / "ate_over_time.png");
  EXPECT_EQ(resolution_100, 3937u);  // 100 per inch in pixels per metre, rounded
  EXPECT_EQ(resolution_300, 11811u);
  EXPECT_NEAR(double(width_300) / width_100, 3.0, 0.05);
}

// `run` and `track` take the same figure options for their evaluation's figures; `run` also
// draws the SVGs its page shows, unless there is no page.
TEST(Figures, RunAndTrackWriteTheFiguresAskedFor) {
  REQUIRE_MATPLOTLIB();
  SLAMKIT_REQUIRE_DATA(sequence, "rgbd_dataset_freiburg1_desk_9frames");
  const fs::path dir = test::temp_dir("figures_run");
  const char* kFigures[] = {"trajectory_xy", "ate_over_time", "rpe_over_time"};
  const auto has = [&](const char* run, const char* name, const char* ext) {
    return fs::exists(dir / run / (std::string(name) + ext));
  };
  std::string log;
  ASSERT_EQ(test::run_slamkit("run " + quoted(sequence) + " --out " + quoted(dir / "run") +
                                  " --plot-format pdf --threads 1",
                              &log),
            0)
      << log;
  ASSERT_EQ(test::run_slamkit("run " + quoted(sequence) + " --out " +
                                  quoted(dir / "run_no_page") +
                                  " --plot-format pdf --no-report --threads 1",
                              &log),
            0)
      << log;
  for (const char* name : kFigures) {
    EXPECT_EQ(head(dir / "run" / (std::string(name) + ".pdf"), 5), "%PDF-") << name;
    EXPECT_TRUE(has("run", name, ".svg")) << name;  // for the page
    EXPECT_FALSE(has("run", name, ".png")) << name;
    EXPECT_TRUE(has("run_no_page", name, ".pdf")) << name;
    EXPECT_FALSE(has("run_no_page", name, ".svg")) << name;
  }
  EXPECT_NE(test::read_text(dir / "run" / "report.html").find("<svg"), std::string::npos);
  ASSERT_EQ(test::run_slamkit("track " + quoted(sequence) + " --out " + quoted(dir / "track") +
                                  " --plot-format png --dpi 100 --threads 1",
                              &log),
            0)
      << log;
  for (const char* name : kFigures) {
    EXPECT_EQ(png_width_and_resolution(dir / "track" / (std::string(name) + ".png")).second,
              3937u)
        << name;
    EXPECT_FALSE(has("track", name, ".svg")) << name;
  }
}

// Two runs of one groundtruth are drawn together; a run of another groundtruth is refused by
// the script with one line naming both runs, after the tables were written.
TEST(Figures, CompareDrawsTheRunsTrajectoriesTogetherAndRefusesAnotherGroundtruth) {
  REQUIRE_MATPLOTLIB();
  const fs::path dir = test::temp_dir("figures");
  const fs::path gt = write_tum(dir / "gt.txt", 150);
  const fs::path other_gt = write_tum(dir / "other_gt.txt", 140);
  std::string log;
  const auto evaluate = [&](const fs::path& truth, double wobble, const std::string& name) {
    const fs::path est = write_tum(dir / (name + ".txt"), 150, wobble);
    return test::run_slamkit("eval ate " + quoted(truth) + " " + quoted(est) + " --out " +
                                 quoted(dir / name) + " --no-plot --quiet",
                             &log);
  };
  ASSERT_EQ(evaluate(gt, 0.01, "one"), 0) << log;
  ASSERT_EQ(evaluate(gt, 0.03, "two"), 0) << log;
  ASSERT_EQ(evaluate(other_gt, 0.01, "elsewhere"), 0) << log;

  ASSERT_EQ(test::run_slamkit("eval compare " + quoted(dir / "one") + " " + quoted(dir / "two") +
                                  " --out " + quoted(dir / "cmp") +
                                  " --trajectories --planes xy,xz --plot-format svg --quiet",
                              &log),
            0)
      << log;
  for (const char* name : {"trajectories_xy", "trajectories_xz", "trajectories_xyz"}) {
    const std::string svg = test::read_text(dir / "cmp" / (std::string(name) + ".svg"));
    EXPECT_NE(svg.find("<svg"), std::string::npos) << name;
    // The legend names each run (SVG keeps text as text).
    EXPECT_NE(svg.find(">one<"), std::string::npos) << name;
    EXPECT_NE(svg.find(">two<"), std::string::npos) << name;
  }
  for (const char* table : {"table.csv", "table.md", "table.tex"})
    EXPECT_TRUE(fs::exists(dir / "cmp" / table)) << table;

  EXPECT_EQ(
      test::run_slamkit("eval compare " + quoted(dir / "one") + " " + quoted(dir / "elsewhere") +
                            " --out " + quoted(dir / "bad") + " --trajectories",
                        &log),
      1);
  EXPECT_NE(log.find("plot.py: no trajectories figure: runs 'one' and 'elsewhere' were evaluated "
                     "against different groundtruth (" +
                     gt.string() + "; " + other_gt.string() + ")"),
            std::string::npos)
      << log;
  EXPECT_EQ(log.find("Traceback"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "bad" / "trajectories_xy.png"));
  EXPECT_TRUE(fs::exists(dir / "bad" / "table.tex"));
  EXPECT_TRUE(fs::exists(dir / "bad" / "ate_comparison.png"));  // the box plot is drawn anyway
}

}  // namespace
}  // namespace slamkit::eval
