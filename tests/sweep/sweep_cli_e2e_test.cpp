// `slamkit sweep` end to end on this machine: tests/sweep/tiny.yaml (one 40-frame synthetic
// sequence, 2 ORB feature counts x 2 seeds) planned, run with --backend local --jobs 2, followed
// with status, collected into the report, resumed, a lost run reported as missing (collect exits 1)
// and run again by `sweep task` with the same numbers; bad input exits 2 naming the line.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

// runs.csv as index -> column -> value.
std::map<int, std::map<std::string, std::string>> read_runs_csv(const fs::path& file) {
  std::stringstream in(test::read_text(file));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  std::map<int, std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::map<std::string, std::string> row;
    std::string field;
    for (size_t k = 0; k < header.size() && std::getline(fields, field, ','); ++k)
      row[header[k]] = field;
    rows[std::stoi(row.at("index"))] = row;
  }
  return rows;
}

TEST(SweepCli, LocalSweepPlannedRunCollectedResumedAndRepaired) {
  const fs::path dir = test::temp_dir("sweep_cli");
  const fs::path sweep_file = fs::path(SLAMKIT_SOURCE_DIR) / "tests" / "sweep" / "tiny.yaml";
  const fs::path out = dir / "out";
  std::string output;

  ASSERT_EQ(
      test::run_slamkit("sweep plan " + sweep_file.string() + " --out " + out.string(), &output), 0)
      << output;
  EXPECT_NE(output.find("tiny: 1 entries x 2 variants x 2 seeds (1, 2) = 4 jobs"),
            std::string::npos)
      << output;

  ASSERT_EQ(test::run_slamkit("sweep run " + out.string() + " --backend local --jobs 2", &output),
            0)
      << output;
  EXPECT_NE(output.find("4 jobs: 4 finished (0 reused), 0 failed"), std::string::npos) << output;

  ASSERT_EQ(test::run_slamkit("sweep status " + out.string(), &output), 0) << output;
  EXPECT_NE(output.find("4 jobs: 4 done, 0 pending, 0 running, 0 requeued, 0 failed, 0 missing"),
            std::string::npos)
      << output;

  ASSERT_EQ(test::run_slamkit("sweep collect " + out.string(), &output), 0) << output;
  EXPECT_NE(output.find("best        ATE RMSE: num_features-"), std::string::npos) << output;
  const std::string report = test::read_text(out / "report.md");
  EXPECT_NE(report.find("**COMPLETE: 4 of 4 runs finished**"), std::string::npos) << report;
  EXPECT_NE(report.find("| ATE RMSE | num_features-"), std::string::npos) << report;
  EXPECT_NE(report.find("| RPE trans RMSE | num_features-"), std::string::npos) << report;
  EXPECT_EQ(report.find("Missing or failed"), std::string::npos);
  EXPECT_NE(test::read_text(out / "report.html").find("data:image/png;base64,"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "ate_heatmap.png"));
  EXPECT_EQ(test::read_text(out / "ate_table.csv").rfind("variant,desk\nnum_features-300,", 0), 0u);

  const auto runs = read_runs_csv(out / "runs.csv");
  ASSERT_EQ(runs.size(), 4u);
  for (const auto& [index, row] : runs) {
    EXPECT_EQ(row.at("state"), "done");
    EXPECT_FALSE(row.at("ate_rmse").empty()) << index;
  }
  // A seed is another sequence (its own noise): the same variant measures differently.
  EXPECT_NE(runs.at(0).at("ate_rmse"), runs.at(1).at("ate_rmse"));
  // Each run's settings file holds its variant and seed.
  const std::string settings = test::read_text(out / "settings/num_features-600/desk/seed2.yaml");
  EXPECT_NE(settings.find("num_features: 600"), std::string::npos);

  // Resumable: nothing runs again.
  ASSERT_EQ(test::run_slamkit("sweep run " + out.string() + " --jobs 2", &output), 0) << output;
  EXPECT_NE(output.find("4 jobs: 4 finished (4 reused), 0 failed"), std::string::npos) << output;

  // Every run folder was published whole: no attempt folder or temporary is left.
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".attempt."), std::string::npos) << e.path();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << e.path();
  }

  // A lost run is named, and collect merges nothing until it is back unless asked.
  const fs::path lost = out / "runs/num_features-600/desk/seed2";
  fs::remove_all(lost);
  fs::remove(out / "report.md");
  EXPECT_EQ(test::run_slamkit("sweep collect " + out.string(), &output), 1) << output;
  EXPECT_NE(output.find("missing     3  num_features-600/desk/seed2"), std::string::npos) << output;
  EXPECT_NE(output.find("INCOMPLETE  3 of 4 runs finished"), std::string::npos) << output;
  EXPECT_NE(output.find("nothing merged"), std::string::npos) << output;
  // A local sweep is resumed by running it again, not by resubmitting to Slurm.
  EXPECT_NE(output.find("run the failed and missing ones again (slamkit sweep run " +
                        out.string() + ")"),
            std::string::npos)
      << output;
  EXPECT_FALSE(fs::exists(out / "report.md"));
  EXPECT_EQ(test::run_slamkit("sweep collect --allow-incomplete " + out.string(), &output), 1)
      << output;
  EXPECT_NE(test::read_text(out / "report.md").find("## Missing or failed tasks"),
            std::string::npos);

  // A dead attempt left a half-written folder (its node died mid-write): the job's next
  // attempt removes it and publishes its own run, whole.
  const fs::path dead = lost.string() + ".attempt.node2.4711";
  fs::create_directories(dead);
  std::ofstream(dead / "run.json") << "{\"status\": \"running\"}\n";
  std::ofstream(dead / "tracking.csv") << "frame,seconds\n0,0.0";
  std::ofstream(dead / "only_in_the_dead_attempt.txt") << "must not reach the run folder\n";
  ASSERT_EQ(test::run_slamkit("sweep status " + out.string(), &output), 0) << output;
  EXPECT_NE(output.find("running     3  num_features-600/desk/seed2"), std::string::npos)
      << output;
  // ...and a render of the job's sequence that died with it left its temporary folder and log.
  const fs::path dead_render = out / "sequences" / "synthetic_desk_40_seed2.tmp.node2.4711";
  fs::create_directories(dead_render / "rgb");
  std::ofstream(dead_render.string() + ".log") << "rendering\n";

  // One job alone, as an array task runs it, with all cores: the same numbers as before.
  ASSERT_EQ(test::run_slamkit("sweep task " + out.string() + " 3", &output), 0) << output;
  EXPECT_NE(output.find("1 attempt folder(s) of a dead attempt removed"), std::string::npos)
      << output;
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_FALSE(fs::exists(lost / "only_in_the_dead_attempt.txt"));
  EXPECT_FALSE(fs::exists(dead_render));
  EXPECT_FALSE(fs::exists(dead_render.string() + ".log"));
  ASSERT_EQ(test::run_slamkit("sweep collect " + out.string(), &output), 0) << output;
  const auto again = read_runs_csv(out / "runs.csv");
  for (const char* metric : {"ate_rmse", "rpe_trans_rmse", "frames_lost", "map_completeness"})
    EXPECT_EQ(again.at(3).at(metric), runs.at(3).at(metric)) << metric;
}

TEST(SweepCli, BadInputExitsTwoNamingFileAndLine) {
  const fs::path dir = test::temp_dir("sweep_cli_bad");
  const fs::path sweep_file = dir / "bad.yaml";
  std::ofstream(sweep_file) << "suite:\n  entries:\n    - name: d\n      synthetic: {preset: "
                               "desk, frames: 30}\ngrid:\n  orb.num_features: [0]\n";
  std::string output;
  EXPECT_EQ(test::run_slamkit(
                "sweep plan " + sweep_file.string() + " --out " + (dir / "out").string(), &output),
            2);
  EXPECT_NE(output.find(sweep_file.string() + ":6: orb.num_features: 0 is outside 1..100000"),
            std::string::npos)
      << output;
  EXPECT_FALSE(fs::exists(dir / "out" / "jobs.tsv"));
  EXPECT_EQ(test::run_slamkit("sweep status " + (dir / "nowhere").string(), &output), 2);
  EXPECT_NE(output.find("no sweep plan here"), std::string::npos) << output;
  EXPECT_EQ(test::run_slamkit("sweep task " + (dir / "nowhere").string() + " 0", &output), 2);
}

// The sweeps shipped in results/ stay valid as settings and suites change: each plans (no
// run) with its documented number of jobs.
TEST(SweepCli, ShippedSweepsPlan) {
  const fs::path dir = test::temp_dir("sweep_shipped");
  const fs::path results = fs::path(SLAMKIT_SOURCE_DIR) / "results";
  const std::map<std::string, std::string> expected = {
      {"sweep-orb-features.yaml",
       "orb-features: 4 entries x 3 variants x the suite's seeds = 12 jobs"},
      {"sweep-dense-seeds.yaml",
       "dense-seeds: 2 entries x 2 variants x 3 seeds (1, 2, 3) = 12 jobs"},
      {"sweep-keyframe-culling.yaml",
       "keyframe-culling: 3 entries x 3 variants x 3 seeds (1, 2, 3) = 27 jobs"},
      {"sweep-kinect-cluster.yaml",
       "kinect-cluster: 3 entries x 2 variants x 2 seeds (1, 2) = 12 jobs"},
  };
  int found = 0;
  for (const auto& entry : fs::directory_iterator(results)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("sweep-", 0) != 0) continue;
    ++found;
    ASSERT_TRUE(expected.count(name)) << name << " has no expected plan here";
    std::string output;
    ASSERT_EQ(
        test::run_slamkit("sweep plan " + entry.path().string() + " --out " + (dir / name).string(),
                          &output),
        0)
        << output;
    EXPECT_NE(output.find(expected.at(name)), std::string::npos) << output;
  }
  EXPECT_EQ(found, int(expected.size()));
}

}  // namespace
}  // namespace slamkit
