// `slamkit eval` end to end: files in, files and exit codes out.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

// A TUM file with n poses at 30 Hz from `start`, moving on a circle; `shift` moves positions.
fs::path write_tum(const fs::path& path, size_t n, double start, double shift = 0.0,
                   const std::string& extra_lines = "") {
  std::ofstream out(path);
  out << "# timestamp tx ty tz qx qy qz qw\n";
  out.precision(17);
  for (size_t k = 0; k < n; ++k) {
    const double s = 0.05 * double(k);
    out << start + double(k) / 30.0 << " " << std::cos(s) + shift << " " << std::sin(s) << " "
        << 0.1 * s << " 0 0 " << std::sin(s / 2) << " " << std::cos(s / 2) << "\n";
  }
  out << extra_lines;
  return path;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(EvalCli, AteThenRpeShareOneMetricsFileAndWriteCsvAndAlignedTrajectory) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 300, 1000.0);
  const fs::path est = write_tum(dir / "est.txt", 300, 1000.0, 0.02);
  const fs::path out = dir / "run";
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) +
                                  " --align none --out " + quoted(out) + " --no-plot",
                              &log),
            0)
      << log;
  EXPECT_NE(log.find("absolute_translational_error.rmse 0.020000 m"), std::string::npos) << log;
  ASSERT_EQ(test::run_slamkit("eval rpe " + quoted(gt) + " " + quoted(est) + " --json " +
                                  quoted(out / "metrics.json") + " --quiet",
                              &log),
            0)
      << log;
  EXPECT_EQ(log, "");  // --quiet prints nothing

  const nlohmann::json m = read_json(out / "metrics.json");
  EXPECT_EQ(m["ate"]["pairs"], 300);
  EXPECT_NEAR(m["ate"]["rmse"].get<double>(), 0.02, 1e-12);
  EXPECT_EQ(m["ate"]["alignment"]["method"], "none");
  EXPECT_EQ(m["rpe"]["unit"], "s");
  EXPECT_EQ(m["rpe"]["convention"], "tum");
  EXPECT_LT(m["rpe"]["trans"]["max"].get<double>(), 1e-9);
  EXPECT_EQ(m["inputs"]["estimate"]["poses"], 300);
  EXPECT_EQ(m["inputs"]["groundtruth"]["fnv1a64"].get<std::string>().size(), 16u);
  EXPECT_EQ(m["settings"]["system_name"], "est");
  EXPECT_DOUBLE_EQ(m["coverage"]["fraction_of_groundtruth"].get<double>(), 1.0);

  std::ifstream csv(out / "errors.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "time,ate_m,est_tx,est_ty,est_tz,gt_tx,gt_ty,gt_tz,rot_deg");
  EXPECT_TRUE(fs::exists(out / "aligned.txt"));
  EXPECT_FALSE(fs::exists(out / "rpe.csv"));  // rpe wrote only where --json pointed
}

TEST(EvalCli, BadInputsGiveOneClearLineAndExitCode2) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 100, 1000.0);
  std::string log;

  const fs::path seven = dir / "seven.txt";
  std::ofstream(seven) << "1000.0 1 2 3 0 0 0\n";
  EXPECT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(seven), &log), 2);
  EXPECT_NE(log.find("seven.txt:1: expected 8 fields"), std::string::npos) << log;

  const fs::path empty = dir / "empty.txt";
  std::ofstream(empty) << "# nothing\n";
  EXPECT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(empty), &log), 2);
  EXPECT_NE(log.find("no valid pose"), std::string::npos) << log;

  const fs::path later = write_tum(dir / "later.txt", 100, 5000.0);
  EXPECT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(later), &log), 2);
  EXPECT_NE(log.find("only 0 estimated pose(s) matched groundtruth within 0.02 s"),
            std::string::npos)
      << log;
  // RPE too says that nothing overlaps, in one line, without a coverage warning before it.
  EXPECT_EQ(test::run_slamkit("eval rpe " + quoted(gt) + " " + quoted(later), &log), 2);
  EXPECT_EQ(log.rfind("slamkit: error: ", 0), 0u) << log;
  EXPECT_NE(log.find("only 0 estimated pose(s) matched groundtruth within 0.02 s"),
            std::string::npos)
      << log;
}

TEST(EvalCli, SkippedLinesAndPartialCoverageAreReportedAndTheOverlapEvaluated) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 200, 1000.0);
  // Half the groundtruth span, plus a NaN line and a zero quaternion.
  const fs::path est = write_tum(dir / "est.txt", 100, 1000.0, 0.0,
                                 "1004.0 nan 0 0 0 0 0 1\n1004.1 1 2 3 0 0 0 0\n");
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est), &log), 0) << log;
  EXPECT_NE(log.find("est.txt:102: non-finite value, line skipped"), std::string::npos) << log;
  EXPECT_NE(log.find("est.txt:103: zero quaternion, line skipped"), std::string::npos) << log;
  EXPECT_NE(log.find("estimate covers 50% of groundtruth time span"), std::string::npos) << log;
  EXPECT_NE(log.find("compared_pose_pairs 100 pairs"), std::string::npos) << log;
}

// --convention evo: association tolerance 0.01 s (evo's --t_max_diff), first of repeated
// stamps kept, evo's RPE. Estimate stamps 15 ms late match under tum's 0.02 s, not evo's.
TEST(EvalCli, EvoConventionSetsEvosDefaultsAndTheOptionsStillOverrideThem) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 100, 1000.0);
  const fs::path late = write_tum(dir / "late.txt", 100, 1000.015);
  std::string log;
  EXPECT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(late) + " --quiet", &log), 0)
      << log;
  EXPECT_EQ(
      test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(late) + " --convention evo", &log),
      2);
  EXPECT_NE(log.find("matched groundtruth within 0.01 s (offset 0 s, evo association)"),
            std::string::npos)
      << log;
  ASSERT_EQ(test::run_slamkit("eval all " + quoted(gt) + " " + quoted(late) +
                                  " --convention evo --max-diff 0.02 --unit f --quiet --json " +
                                  quoted(dir / "m.json"),
                              &log),
            0)
      << log;
  const nlohmann::json m = read_json(dir / "m.json");
  EXPECT_EQ(m["settings"]["association"], "evo");
  EXPECT_EQ(m["settings"]["duplicate_stamps"], "all");
  EXPECT_EQ(m["settings"]["max_diff"], 0.02);
  EXPECT_EQ(m["rpe"]["convention"], "evo");
  EXPECT_EQ(m["rpe"]["pairs"], 99);  // evo keeps the last pair: (0,1) .. (98,99)
}

// A monocular-like case: an estimate at half scale. `eval rpe --align sim3` scales it
// first (scale 2 by construction), so consecutive-frame errors vanish; without, each step of
// the estimate is half the groundtruth's.
TEST(EvalCli, RpeWithSim3AlignmentScalesTheEstimateFirst) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 200, 1000.0);
  std::ifstream in(gt);
  std::ofstream half(dir / "half.txt");
  half.precision(17);
  for (std::string line; std::getline(in, line);) {
    if (line[0] == '#') continue;
    std::istringstream fields(line);
    double v[8];
    for (double& x : v) fields >> x;
    half << v[0] << " " << v[1] / 2 << " " << v[2] / 2 << " " << v[3] / 2 << " " << v[4] << " "
         << v[5] << " " << v[6] << " " << v[7] << "\n";
  }
  half.close();
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval rpe " + quoted(gt) + " " + quoted(dir / "half.txt") +
                                  " --convention evo --unit f --align sim3 --json " +
                                  quoted(dir / "m.json"),
                              &log),
            0)
      << log;
  const nlohmann::json m = read_json(dir / "m.json");
  EXPECT_NEAR(m["rpe"]["scale"].get<double>(), 2.0, 1e-9);
  EXPECT_LT(m["rpe"]["trans"]["max"].get<double>(), 1e-9);
  EXPECT_NE(log.find("estimate scaled by 2.000000"), std::string::npos) << log;
}

TEST(EvalCli, NanosecondStampsAreDetectedAndConvertedOnRequest) {
  const fs::path dir = test::temp_dir("eval_cli");
  const auto write_ns = [&](const fs::path& path) {
    std::ofstream out(path);
    for (int k = 0; k < 90; ++k)
      out << 1305031102000000000LL + 33333333LL * k << " " << std::cos(0.05 * k) << " "
          << std::sin(0.05 * k) << " " << 0.01 * k << " 0 0 0 1\n";
    return path;
  };
  const fs::path gt = write_ns(dir / "gt_ns.txt"), est = write_ns(dir / "est_ns.txt");
  std::string log;
  EXPECT_EQ(test::run_slamkit("eval rpe " + quoted(gt) + " " + quoted(est) + " --delta 1", &log),
            2);
  EXPECT_NE(log.find("gt_ns.txt: timestamps reach"), std::string::npos) << log;
  EXPECT_NE(log.find("looks like nanoseconds; pass --time-unit ns"), std::string::npos) << log;
  ASSERT_EQ(test::run_slamkit("eval rpe " + quoted(gt) + " " + quoted(est) +
                                  " --time-unit ns --delta 1 --json " + quoted(dir / "m.json"),
                              &log),
            0)
      << log;
  EXPECT_EQ(read_json(dir / "m.json")["inputs"]["groundtruth"]["start"], 1305031102.0);
  // A delta below the pose spacing (33 ms) pairs poses with themselves: warned.
  ASSERT_EQ(
      test::run_slamkit(
          "eval rpe " + quoted(gt) + " " + quoted(est) + " --time-unit ns --delta 0.001", &log),
      0)
      << log;
  EXPECT_NE(log.find("RPE delta 0.001 s is below the median interval between estimated poses"),
            std::string::npos)
      << log;
}

// Values that overflow the statistics are refused at the line; a metrics.json holding null
// (as older versions wrote) makes `compare` name the file.
TEST(EvalCli, OverflowingValuesAreRefusedAndCompareNamesTheFileItCannotUse) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 100, 1000.0);
  const fs::path est = write_tum(dir / "est.txt", 100, 1000.0, 0.0, "1004.0 1e308 0 0 0 0 0 1\n");
  std::string log;
  EXPECT_EQ(test::run_slamkit("eval all " + quoted(gt) + " " + quoted(est) + " --out " +
                                  quoted(dir / "run") + " --no-plot",
                              &log),
            2);
  EXPECT_NE(log.find("est.txt:102: field 2 is 1e308"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "run" / "metrics.json"));

  fs::create_directories(dir / "old");
  std::ofstream(dir / "old" / "metrics.json")
      << R"({"ate": {"pairs": 100, "rmse": null, "mean": 0.1}, "settings": {}})";
  EXPECT_EQ(test::run_slamkit("eval compare " + quoted(dir / "old") + " --out " + quoted(dir / "c"),
                              &log),
            2);
  EXPECT_NE(log.find((dir / "old" / "metrics.json").string() + ": ate.rmse is null"),
            std::string::npos)
      << log;
  EXPECT_EQ(test::run_slamkit(
                "eval compare " + quoted(dir / "none") + " --out " + quoted(dir / "c"), &log),
            2);
  EXPECT_NE(log.find((dir / "none" / "metrics.json").string() + ": no metrics file"),
            std::string::npos)
      << log;
}

// A run folder whose run.json (slamkit run/track) is not complete is refused, naming the
// file; one made by `eval all` has no run.json and is compared as before.
TEST(EvalCli, CompareRefusesARunFolderThatIsNotComplete) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 100, 1000.0);
  const fs::path est = write_tum(dir / "est.txt", 100, 1000.0, 0.002);
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval all " + quoted(gt) + " " + quoted(est) + " --out " +
                                  quoted(dir / "run") + " --no-plot",
                              &log),
            0)
      << log;
  EXPECT_EQ(test::run_slamkit("eval compare " + quoted(dir / "run") + " --out " + quoted(dir / "c"),
                              &log),
            0)
      << log;
  std::ofstream(dir / "run" / "run.json") << R"({"status": "interrupted", "signal": 15})";
  EXPECT_EQ(test::run_slamkit("eval compare " + quoted(dir / "run") + " --out " + quoted(dir / "c"),
                              &log),
            2);
  EXPECT_NE(log.find((dir / "run" / "run.json").string() +
                     ": the run is not complete (status 'interrupted')"),
            std::string::npos)
      << log;
  std::ofstream(dir / "run" / "run.json") << R"({"status": "complete"})";
  EXPECT_EQ(test::run_slamkit("eval compare " + quoted(dir / "run") + " --out " + quoted(dir / "c"),
                              &log),
            0)
      << log;
}

// The fr1/desk frames 18-26 (0.27 s of nearly straight motion) with a 3 mm estimate: the
// rotation about the line of the positions is not fixed, so no rotational ATE is printed.
TEST(EvalCli, NearlyCollinearPositionsWithholdTheRotationalError) {
  SLAMKIT_REQUIRE_DATA(gt, "rgbd_dataset_freiburg1_desk_9frames/groundtruth.txt");
  const fs::path dir = test::temp_dir("eval_cli");
  std::ifstream in(gt);
  std::ofstream cut(dir / "gt9.txt"), est(dir / "est9.txt");
  cut.precision(17);
  est.precision(17);
  int k = 0;
  for (std::string line; std::getline(in, line);) {
    if (line[0] == '#') continue;
    std::istringstream fields(line);
    double v[8];
    for (double& x : v) fields >> x;
    // The 27 groundtruth poses around the 9 frames (1305031453.2 .. 1305031453.47).
    if (v[0] < 1305031453.20 || v[0] > 1305031453.47) continue;
    cut << line << "\n";
    const double wobble = 0.003 * std::sin(2.1 * k++);
    est << v[0] << " " << v[1] + wobble << " " << v[2] - wobble << " " << v[3] + 0.5 * wobble << " "
        << v[4] << " " << v[5] << " " << v[6] << " " << v[7] << "\n";
  }
  cut.close();
  est.close();
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval ate " + quoted(dir / "gt9.txt") + " " +
                                  quoted(dir / "est9.txt") + " --json " + quoted(dir / "m.json"),
                              &log),
            0)
      << log;
  EXPECT_NE(log.find("absolute_rotational_error withheld: the matched positions fix the "
                     "alignment's rotation only to within"),
            std::string::npos)
      << log;
  const nlohmann::json m = read_json(dir / "m.json");
  EXPECT_FALSE(m["ate"].contains("rot_deg"));
  EXPECT_TRUE(m["ate"].contains("rot_deg_withheld"));
  EXPECT_GT(m["ate"]["alignment"]["rotation_ambiguity_deg"].get<double>(), 10.0);
}

TEST(EvalCli, MissingPlotPythonIsAnErrorOnlyWhenPlotsWereRequested) {
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 100, 1000.0);
  const std::string args = "eval ate " + quoted(gt) + " " + quoted(gt);
  const std::string no_python = "env SLAMKIT_PYTHON=/nonexistent/python3 ";
  std::string log;
  // run_slamkit prefixes the binary; put the environment in front through `env`.
  const std::string binary = SLAMKIT_BINARY;
  const auto run = [&](const std::string& extra) {
    const std::string command = no_python + binary + " " + args + " " + extra + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    char buffer[4096];
    log.clear();
    while (fgets(buffer, sizeof buffer, pipe)) log += buffer;
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(run("--plot " + quoted(dir / "plots")), 1);
  EXPECT_NE(log.find("no ate plots drawn: no Python interpreter at '/nonexistent/python3'"),
            std::string::npos)
      << log;
  EXPECT_TRUE(fs::exists(dir / "plots" / "metrics.json"));
  EXPECT_TRUE(fs::exists(dir / "plots" / "errors.csv"));
  EXPECT_EQ(run("--out " + quoted(dir / "out")), 0);
  EXPECT_NE(log.find("note: no ate plots drawn"), std::string::npos) << log;
}

TEST(EvalCli, AFullDiskUnderAPlotGivesOneLineNamingTheFileNotATraceback) {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") != 0)
    GTEST_SKIP() << "/usr/bin/python3 cannot import matplotlib (scripts/setup.sh installs it)";
  const fs::path dir = test::temp_dir("eval_cli");
  const fs::path gt = write_tum(dir / "gt.txt", 100, 1000.0);
  fs::create_directories(dir / "plots");
  // Writing to /dev/full fails with ENOSPC: the plot's PNG meets a full disk.
  fs::create_symlink("/dev/full", dir / "plots" / "ate_over_time.png");
  std::string log;
  EXPECT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(gt) + " --plot " +
                                  quoted(dir / "plots"),
                              &log),
            1);
  EXPECT_NE(log.find("plot.py: no ate figure: cannot write " +
                     (dir / "plots" / "ate_over_time.png").string() +
                     ": No space left on device"),
            std::string::npos)
      << log;
  EXPECT_EQ(log.find("Traceback (most recent call last)"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(dir / "plots" / "metrics.json"));
}

TEST(EvalCli, RealFr2DeskAllWritesReferenceNumbersAndPlotsAndCompareTablesThem) {
  SLAMKIT_REQUIRE_DATA(gt, "trajectories/fr2_desk/groundtruth.txt");
  SLAMKIT_REQUIRE_DATA(est, "trajectories/fr2_desk/orbslam.txt");
  const fs::path dir = test::temp_dir("eval_cli");
  std::string log;
  ASSERT_EQ(test::run_slamkit("eval all " + quoted(gt) + " " + quoted(est) + " --out " +
                                  quoted(dir / "orbslam") + " --quiet",
                              &log),
            0)
      << log;
  const nlohmann::json m = read_json(dir / "orbslam" / "metrics.json");
  EXPECT_EQ(m["ate"]["pairs"], 2223);
  EXPECT_NEAR(m["ate"]["rmse"].get<double>(), 0.008144, 5e-7);
  EXPECT_EQ(m["rpe"]["pairs"], 1998);
  EXPECT_NEAR(m["rpe"]["trans"]["rmse"].get<double>(), 0.007161, 5e-7);
  EXPECT_EQ(m["inputs"]["groundtruth"]["duplicate_stamps_dropped"], 1);
  const bool can_plot = std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") == 0;
  if (can_plot) {
    for (const char* name : {"ate_over_time", "trajectory_xy", "rpe_over_time"}) {
      EXPECT_TRUE(fs::exists(dir / "orbslam" / (std::string(name) + ".png"))) << name;
      EXPECT_TRUE(fs::exists(dir / "orbslam" / (std::string(name) + ".svg"))) << name;
    }
  }

  ASSERT_EQ(test::run_slamkit("eval ate " + quoted(gt) + " " + quoted(est) +
                                  " --align sim3 --system-name 'ORB-SLAM sim3' --no-plot --out " +
                                  quoted(dir / "sim3") + " --quiet",
                              &log),
            0)
      << log;
  ASSERT_EQ(test::run_slamkit("eval compare " + quoted(dir / "orbslam") + " " +
                                  quoted(dir / "sim3") + " --out " + quoted(dir / "cmp"),
                              &log),
            0)
      << log;
  std::ifstream md(dir / "cmp" / "comparison.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("| orbslam | fr2_desk | 2223 | 0.008144 |"), std::string::npos)
      << text.str();
  EXPECT_NE(text.str().find("| ORB-SLAM sim3 | fr2_desk |"), std::string::npos) << text.str();
  EXPECT_TRUE(fs::exists(dir / "cmp" / "comparison.csv"));
  // The paper tables: every digit in CSV, rounded to 5 decimals (3 digits of 0.00619) in LaTeX.
  EXPECT_NE(test::read_text(dir / "cmp" / "table.csv").find("\norbslam,0.00814396"),
            std::string::npos);
  EXPECT_NE(test::read_text(dir / "cmp" / "table.tex").find("\norbslam & 0.00814 & "),
            std::string::npos)
      << test::read_text(dir / "cmp" / "table.tex");
  if (can_plot) {
    EXPECT_TRUE(fs::exists(dir / "cmp" / "ate_comparison.png"));
  }
}

}  // namespace
}  // namespace slamkit::eval
