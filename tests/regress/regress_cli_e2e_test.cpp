// `slamkit regress` end to end on a tiny synthetic suite (40 and 50 frames): baselines written
// and met, a worse setting caught, an interrupted suite resumed with the same report, junit.xml
// in the JUnit shape, the suite's history left alone unless recorded, timing judged against
// baselines from this machine only; the shipped suites against their committed baselines.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include "eval/regression/baseline.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

const char* kTinySuite = R"(suite: tiny
description: two short synthetic sequences for the tests
entries:
  - name: desk
    synthetic: {preset: desk, frames: 40, seed: 3}
  - name: jerk
    synthetic: {preset: jerk, frames: 50}
)";

// The report without what changes from run to run: the date line, and what depends on the
// machine's load (the timing rows, the verdicts' "(warnings)", the count of entries with timing
// warnings).
std::string stable_report(const fs::path& file) {
  static const std::regex warned(" \\(warnings\\)|[0-9]+ with timing warnings");
  std::stringstream in(test::read_text(file)), out;
  for (std::string line; std::getline(in, line);)
    if (line.find("run time") == std::string::npos && line.find("frames/s") == std::string::npos &&
        line.rfind("Suite `", 0) != 0)
      out << std::regex_replace(line, warned, "") << "\n";
  return out.str();
}

// Checks junit.xml with Python's XML parser: testsuites > testsuite > testcase, the counts
// agreeing with the cases, a <failure> with a message on each failing case. Returns the number
// of failures, or -1 when the shape is wrong (the reason printed).
int junit_failures(const fs::path& file) {
  const std::string script =
      "import sys, xml.etree.ElementTree as ET\n"
      "root = ET.parse(sys.argv[1]).getroot()\n"
      "assert root.tag == 'testsuites', root.tag\n"
      "suites = list(root)\n"
      "assert suites and all(s.tag == 'testsuite' for s in suites)\n"
      "failures = 0\n"
      "for s in suites:\n"
      "    cases = list(s)\n"
      "    assert all(c.tag == 'testcase' and c.get('classname') and c.get('name') for c in "
      "cases)\n"
      "    assert int(s.get('tests')) == len(cases)\n"
      "    f = [c for c in cases if c.find('failure') is not None]\n"
      "    assert int(s.get('failures')) == len(f)\n"
      "    assert all(c.find('failure').get('message') for c in f)\n"
      "    assert int(s.get('errors')) == len([c for c in cases if c.find('error') is not None])\n"
      "    failures += len(f)\n"
      "print(failures)\n";
  const fs::path py = file.parent_path() / "check_junit.py";
  std::ofstream(py) << script;
  FILE* pipe =
      popen(("/usr/bin/python3 " + py.string() + " " + file.string() + " 2>&1").c_str(), "r");
  char buffer[4096];
  std::string text;
  while (fgets(buffer, sizeof buffer, pipe)) text += buffer;
  if (pclose(pipe) != 0) {
    ADD_FAILURE() << "junit.xml shape: " << text;
    return -1;
  }
  return std::stoi(text);
}

int run_regress(const std::string& arguments, std::string* output) {
  const int code = test::run_slamkit("regress " + arguments, output);
  std::printf("slamkit regress %s\n%s", arguments.c_str(), output->c_str());
  return code;
}

// Runs `slamkit regress SUITE --out OUT`, killing it and its `slamkit run` child as soon as the
// first entry's run folder is finished.
void run_and_kill_after_first_entry(const fs::path& suite, const fs::path& out) {
  fs::create_directories(out);
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);  // its own process group, so the kill reaches the child runs too
    const std::string log = (out / "killed.log").string();
    if (!freopen(log.c_str(), "w", stdout) || !freopen(log.c_str(), "a", stderr)) _exit(126);
    execl(SLAMKIT_BINARY, "slamkit", "regress", suite.c_str(), "--out", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  const fs::path first_marker = out / "runs" / "desk" / "regress_entry.json";
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(first_marker) &&
         std::chrono::steady_clock::now() - start < std::chrono::minutes(3))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(-pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
}

// One test (ctest runs tests as separate processes, two at a time): the baseline run is
// shared by every step.
TEST(RegressCli, TinySuiteBaselinesPassWorseSettingRegressesKilledRunResumes) {
  const fs::path dir = test::temp_dir("regress_cli");
  const fs::path suite = dir / "tiny.yaml";
  std::ofstream(suite) << kTinySuite;
  const std::string baselines = (dir / "baselines" / "tiny").string();
  // The suite folder's tracked history: a copy of results/history.csv.
  const fs::path tracked = dir / "history.csv";
  fs::copy_file(fs::path(SLAMKIT_SOURCE_DIR) / "results" / "history.csv", tracked);
  const auto lines = [](const std::string& text) {
    return std::count(text.begin(), text.end(), '\n');
  };
  const auto shipped_lines = lines(test::read_text(tracked));
  std::string output;

  // Baselines, with where they came from; the run is recorded in the tracked history too.
  ASSERT_EQ(
      run_regress(suite.string() + " --out " + (dir / "first").string() + " --update-baselines",
                  &output),
      0);
  const std::string baseline = test::read_text(dir / "baselines" / "tiny" / "desk.json");
  for (const char* key : {"\"version\"", "\"settings_hash\"", "\"machine\"", "\"date\"",
                          "\"ate_rmse\"", "\"frames_lost\"", "\"map_completeness\""})
    EXPECT_NE(baseline.find(key), std::string::npos) << key;
  std::string tracked_text = test::read_text(tracked);
  EXPECT_EQ(lines(tracked_text), shipped_lines + 2);

  {
    SCOPED_TRACE("the same suite again passes, reusing the finished runs");
    const fs::path out = dir / "first";
    EXPECT_EQ(run_regress(suite.string() + " --out " + out.string(), &output), 0);
    EXPECT_NE(output.find("reuse       desk"), std::string::npos);
    EXPECT_NE(test::read_text(out / "report.md").find("**PASS: 2 entries"), std::string::npos);
    EXPECT_EQ(junit_failures(out / "junit.xml"), 0);
    // Self-contained: every plot embedded, nothing fetched.
    const std::string html = test::read_text(out / "report.html");
    size_t images = 0;
    for (size_t at = 0; (at = html.find("src=\"data:image/png;base64,", at)) != std::string::npos;
         ++at)
      ++images;
    EXPECT_GE(images, 5u);  // error over time and trajectory per entry, the box plot, history
    EXPECT_EQ(html.find("http"), std::string::npos);
    // Each entry's own page, linked relative to the report.
    EXPECT_NE(html.find("<a href=\"runs/desk/report.html\">"), std::string::npos);
    EXPECT_TRUE(fs::exists(out / "runs" / "desk" / "report.html"));
    // The run's history beside the report: a line per run, not per invocation.
    const std::string history = test::read_text(out / "history.csv");
    EXPECT_EQ(lines(history), 3);
    // The suite's tracked history is the user's to change: byte-unchanged.
    EXPECT_EQ(test::read_text(tracked), tracked_text);
    EXPECT_NE(output.find("history     " + (out / "history.csv").string() + " (" +
                          tracked.string() + " unchanged: --record appends to it)"),
              std::string::npos);
  }
  {
    SCOPED_TRACE("200 ORB features instead of 1000 regress, and the report says where");
    std::string worse = kTinySuite;
    worse.replace(worse.find("entries:"), 0, "settings: {orb: {num_features: 200}}\n");
    std::ofstream(dir / "worse.yaml") << worse;
    const fs::path out = dir / "worse";
    EXPECT_EQ(run_regress((dir / "worse.yaml").string() + " --out " + out.string() +
                              " --baselines " + baselines + " --record",
                          &output),
              1);
    // --record: the two new runs appended to the tracked history, and in the run's own.
    const std::string recorded = test::read_text(tracked);
    EXPECT_EQ(recorded.substr(0, tracked_text.size()), tracked_text);
    EXPECT_EQ(lines(recorded), shipped_lines + 4);
    EXPECT_EQ(lines(test::read_text(out / "history.csv")), 3);
    tracked_text = recorded;
    EXPECT_NE(output.find("REGRESSED   jerk: ATE RMSE"), std::string::npos);
    const std::string report = test::read_text(out / "report.md");
    EXPECT_NE(report.find("**FAIL:"), std::string::npos);
    EXPECT_NE(report.find("| jerk | synthetic jerk, 50 frames, seed 1 | REGRESSED |"),
              std::string::npos);
    EXPECT_NE(report.find("| **REGRESSED** |"), std::string::npos);
    EXPECT_GT(junit_failures(out / "junit.xml"), 0);
    EXPECT_NE(test::read_text(out / "report.html").find("class=\"fail\">REGRESSED"),
              std::string::npos);
  }
  {
    SCOPED_TRACE("killed after its first entry, the suite resumes with the same report");
    const fs::path out = dir / "killed";
    run_and_kill_after_first_entry(suite, out);
    ASSERT_TRUE(fs::exists(out / "runs" / "desk" / "regress_entry.json"));
    EXPECT_FALSE(fs::exists(out / "runs" / "jerk" / "regress_entry.json"));
    EXPECT_FALSE(fs::exists(out / "report.md"));
    EXPECT_EQ(run_regress(suite.string() + " --out " + out.string(), &output), 0);
    EXPECT_NE(output.find("reuse       desk"), std::string::npos);
    EXPECT_NE(output.find("run         jerk"), std::string::npos);
    EXPECT_EQ(stable_report(out / "report.md"), stable_report(dir / "first" / "report.md"));
  }
  {
    SCOPED_TRACE("a finished entry whose run folder was cut later is run again, not reused");
    const fs::path out = dir / "killed";
    std::ofstream(out / "runs" / "jerk" / "run.json", std::ios::trunc)
        << "{\"status\": \"interrupted\", \"signal\": 15}\n";
    EXPECT_EQ(run_regress(suite.string() + " --out " + out.string(), &output), 0);
    EXPECT_NE(output.find("reuse       desk"), std::string::npos);
    EXPECT_NE(output.find("run again   jerk: " + (out / "runs" / "jerk" / "run.json").string() +
                          ": the run is not complete (status 'interrupted')"),
              std::string::npos)
        << output;
    EXPECT_NE(output.find("run         jerk"), std::string::npos);
    EXPECT_EQ(test::read_text(tracked), tracked_text);
  }
  {
    SCOPED_TRACE("timing warns against a baseline from this machine, and only notes another's");
    const fs::path copied = dir / "timing_baselines";
    fs::copy(baselines, copied);
    regress::Baseline fast = *regress::read_baseline(copied / "desk.json");
    fast.metrics["frames_per_second"] = 1e6;  // far faster than any run here
    regress::write_baseline(copied / "desk.json", fast);
    const std::string args =
        suite.string() + " --out " + (dir / "first").string() + " --baselines " + copied.string();
    EXPECT_EQ(run_regress(args, &output), 0);
    EXPECT_NE(output.find("warning     desk: frames/s"), std::string::npos);
    EXPECT_EQ(output.find("timing not compared"), std::string::npos);

    fast.provenance.machine = "Other CPU, 64 cores, Linux 1.0";
    regress::write_baseline(copied / "desk.json", fast);
    EXPECT_EQ(run_regress(args, &output), 0);
    EXPECT_EQ(output.find("warning     desk"), std::string::npos);
    EXPECT_NE(output.find("note        desk: timing not compared: the baseline was measured on "
                          "Other CPU, 64 cores, Linux 1.0, this is " +
                          regress::machine_description()),
              std::string::npos);
    EXPECT_EQ(output.find("note        jerk: timing not compared"), std::string::npos);
    EXPECT_NE(test::read_text(dir / "first" / "report.md").find("| other machine |"),
              std::string::npos);
  }
}

TEST(RegressCliInput, BadSuiteExitsTwoWithOneLineNamingFileAndLine) {
  const fs::path dir = test::temp_dir("regress_bad");
  std::ofstream(dir / "bad.yaml")
      << "entries:\n  - name: a\n    synthetic: {preset: spiral, frames: 40}\n";
  std::string output;
  EXPECT_EQ(
      test::run_slamkit(
          "regress " + (dir / "bad.yaml").string() + " --out " + (dir / "out").string(), &output),
      2);
  EXPECT_EQ(output, "slamkit: error: " + (dir / "bad.yaml").string() +
                        ":3: unknown synthetic preset 'spiral' (desk, loop, lowtexture, jerk, long, lookalike)\n");
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The shipped synthetic suite against its committed baselines (about 100 s of CPU).
TEST(RegressCliSuites, SyntheticPasses) {
  const fs::path out = test::temp_dir("regress_synthetic");
  std::string output;
  EXPECT_EQ(test::run_slamkit("regress " + std::string(SLAMKIT_SOURCE_DIR) +
                                  "/results/synthetic.yaml --jobs 2 --out " + out.string(),
                              &output),
            0)
      << output;
}

// CI runs this one with SLAMKIT_DATA: the real pieces against their committed baselines.
TEST(RegressCliSuites, TumPiecesPass) {
  SLAMKIT_REQUIRE_DATA(data, "rgbd_dataset_freiburg2_desk_first50");
  const fs::path out = test::temp_dir("regress_tum_pieces");
  std::string output;
  EXPECT_EQ(test::run_slamkit("regress " + std::string(SLAMKIT_SOURCE_DIR) +
                                  "/results/tum-pieces.yaml --data " + data.parent_path().string() +
                                  " --out " + out.string(),
                              &output),
            0)
      << output;
}

}  // namespace
}  // namespace slamkit
