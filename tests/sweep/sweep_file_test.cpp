// Sweep files and plans: the grid's cross product and its names, named variants, seeds, the
// settings each job runs with, jobs.tsv, and errors that name the sweep file, line and key.
#include "eval/sweep/sweep_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "eval/sweep/plan.h"
#include "support/test_data.h"

namespace slamkit::sweep {
namespace {

namespace fs = std::filesystem;

const char* kSuite = R"(suite:
  entries:
    - name: desk
      synthetic: {preset: desk, frames: 40, seed: 3}
    - name: loop
      synthetic: {preset: loop, frames: 50}
      settings: {orb: {num_features: 700}}
)";

struct Fixture {
  fs::path dir = test::temp_dir("sweep_file");
  regress::SuiteContext context;
  Fixture() {
    context.presets = {"desk", "loop"};
    context.tum_names = [] { return std::vector<std::string>{}; };
  }
  fs::path write(const std::string& text, const std::string& name = "sweep.yaml") const {
    const fs::path file = dir / name;
    std::ofstream(file) << text;
    return file;
  }
  // The message of the InputError that loading `text` throws.
  std::string error(const std::string& text) const {
    try {
      load_sweep(write(text), context);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST(SweepFile, GridIsTheCrossProductFirstKeySlowest) {
  Fixture f;
  const Sweep sweep = load_sweep(f.write(std::string(kSuite) + R"(grid:
  orb.num_features: [500, 1000]
  tracking.ransac.max_iterations: [50, 200]
seeds: [1, 2]
rank_by: [ate_rmse, frames_lost]
)"),
                                 f.context);
  EXPECT_EQ(sweep.name, "sweep");
  ASSERT_EQ(sweep.variants.size(), 4u);
  EXPECT_EQ(sweep.variants[0].name, "num_features-500_max_iterations-50");
  EXPECT_EQ(sweep.variants[1].name, "num_features-500_max_iterations-200");
  EXPECT_EQ(sweep.variants[3].name, "num_features-1000_max_iterations-200");
  EXPECT_EQ(sweep.seeds, (std::vector<uint64_t>{1, 2}));
  EXPECT_EQ(sweep.rank_by, (std::vector<std::string>{"ate_rmse", "frames_lost"}));
  ASSERT_EQ(sweep.suite.entries.size(), 2u);

  // The variant over the entry's own settings; the seed into the sequence and the pipeline.
  const uint64_t seed = 2;
  const regress::SuiteEntry loop =
      variant_entry(sweep, sweep.suite.entries[1], sweep.variants[2], &seed);
  EXPECT_EQ(loop.settings.orb.num_features, 1000);
  EXPECT_EQ(loop.settings.tracking.ransac.max_iterations, 50);
  EXPECT_EQ(loop.settings.tracking.ransac.seed, 2u);
  EXPECT_EQ(loop.sequence.seed, 2u);
  EXPECT_TRUE(loop.has_overrides);
}

TEST(SweepFile, NamedVariantsWithNestedOrDottedKeys) {
  Fixture f;
  const Sweep sweep = load_sweep(f.write(std::string(kSuite) + R"(variants:
  - name: paper
    settings:
      orb: {spread_over_image: false}
      tracking.point_to_plane.normal_smoothing_diameter: 0
  - name: defaults
)"),
                                 f.context);
  ASSERT_EQ(sweep.variants.size(), 2u);
  EXPECT_EQ(sweep.variants[0].overrides.size(), 2u);
  EXPECT_TRUE(sweep.seeds.empty());
  EXPECT_EQ(sweep.rank_by, std::vector<std::string>{"ate_rmse"});
  const regress::SuiteEntry desk =
      variant_entry(sweep, sweep.suite.entries[0], sweep.variants[0], nullptr);
  EXPECT_FALSE(desk.settings.orb.spread_over_image);
  EXPECT_EQ(desk.settings.tracking.point_to_plane.normal_smoothing_diameter, 0);
  EXPECT_EQ(desk.sequence.seed, 3u);  // no seeds: the suite's own
  EXPECT_FALSE(
      variant_entry(sweep, sweep.suite.entries[0], sweep.variants[1], nullptr).has_overrides);
}

TEST(SweepFile, ASuiteFileRelativeToTheSweep) {
  Fixture f;
  f.write("entries:\n  - name: d\n    synthetic: {preset: desk, frames: 30}\n", "mine.yaml");
  const Sweep sweep =
      load_sweep(f.write("suite: mine.yaml\ngrid: {orb.num_features: [300]}\n"), f.context);
  EXPECT_EQ(sweep.suite.name, "mine");
  EXPECT_EQ(sweep.suite.entries.at(0).name, "d");
}

TEST(SweepFile, ErrorsNameTheFileLineAndKey) {
  Fixture f;
  const std::string file = (f.dir / "sweep.yaml").string();
  const std::string head = kSuite;  // 7 lines
  EXPECT_EQ(f.error(head + "grid:\n  orb.num_features: [500, -5]\n"),
            file + ":9: orb.num_features: -5 is outside 1..100000");
  EXPECT_EQ(f.error(head + "grid:\n  orb.num_featurs: [500]\n"),
            file + ":9: unknown setting 'orb.num_featurs'");
  EXPECT_EQ(f.error(head + "grid:\n  orb.num_features: []\n"),
            file + ":9: orb.num_features needs a non-empty list of values");
  EXPECT_EQ(
      f.error(head + "variants:\n  - name: a\n    settings:\n      orb: {fast_type: fast7}\n"),
      file + ":11: 'fast7' is not a value of orb.fast_type (fast9 or fast12)");
  EXPECT_EQ(f.error(head + "variants:\n  - name: a\n    settings: {orb: {num_featurs: 5}}\n"),
            file + ":10: unknown setting 'orb.num_featurs'");
  EXPECT_EQ(f.error(head + "grid:\n  tracking.ransac.seed: [1, 2]\nseeds: [1]\n"),
            file +
                ":9: tracking.ransac.seed is what the sweep's seeds set: drop it here or "
                "drop seeds");
  EXPECT_EQ(f.error(head + "seeds: [1, 1]\n"), file + ":8: seed 1 is listed twice");
  EXPECT_EQ(f.error(head + "rank_by: [ate]\n").rfind(file + ":8: unknown metric 'ate' (", 0), 0u);
  EXPECT_EQ(f.error(head + "grid: {orb.num_features: [1]}\nvariants: [{name: a}]\n"),
            file + ":9: give 'grid' or 'variants', not both");
  EXPECT_EQ(f.error(head + "grids: {}\n").rfind(file + ":8: unknown key 'grids'", 0), 0u);
  EXPECT_EQ(f.error(head + "variants:\n  - name: a/b\n"),
            file + ":9: variant name 'a/b' may hold only letters, digits, '_', '-' and '.'");
  // The suite's own checks, at the sweep file's lines.
  EXPECT_EQ(f.error("suite:\n  entries:\n    - name: x\n      synthetic: {preset: attic, "
                    "frames: 9}\n"),
            file + ":4: unknown synthetic preset 'attic' (desk, loop)");
  EXPECT_EQ(f.error("suite: nowhere.yaml\n"),
            file + ":1: suite file '" + (f.dir / "nowhere.yaml").string() + "' not found");
}

TEST(SweepPlan, WritesOnlyJobsTsvAndReadsItBack) {
  Fixture f;
  const fs::path sweep_file =
      f.write(std::string(kSuite) + "grid: {orb.num_features: [500, 1000]}\nseeds: [1, 2]\n");
  const fs::path dir = f.dir / "plan";
  const Plan plan = write_plan(sweep_file, dir, f.context);
  ASSERT_EQ(plan.jobs.size(), 8u);  // 2 entries x 2 variants x 2 seeds
  std::vector<fs::path> written;
  for (const auto& e : fs::directory_iterator(dir)) written.push_back(e.path().filename());
  EXPECT_EQ(written, std::vector<fs::path>{"jobs.tsv"});

  const std::string tsv = test::read_text(dir / "jobs.tsv");
  EXPECT_NE(tsv.find("# sweep\t" + sweep_file.string() + "\n"), std::string::npos);
  EXPECT_NE(tsv.find("index\tentry\tvariant\tseed\trun_folder\n"
                     "0\tdesk\tnum_features-500\t1\truns/num_features-500/desk/seed1\n"
                     "1\tdesk\tnum_features-500\t2\truns/num_features-500/desk/seed2\n"
                     "2\tdesk\tnum_features-1000\t1\truns/num_features-1000/desk/seed1\n"),
            std::string::npos);
  EXPECT_NE(tsv.find("7\tloop\tnum_features-1000\t2\truns/num_features-1000/loop/seed2\n"),
            std::string::npos);

  const Plan read = load_plan(dir, f.context);
  ASSERT_EQ(read.jobs.size(), 8u);
  const regress::RunRequest r = read.request(7);
  EXPECT_EQ(r.label, "num_features-1000/loop/seed2");
  EXPECT_EQ(r.dir, dir / "runs/num_features-1000/loop/seed2");
  EXPECT_EQ(r.settings_file, dir / "settings/num_features-1000/loop/seed2.yaml");
  EXPECT_EQ(r.entry->settings.orb.num_features, 1000);  // the variant over the entry's 700
  EXPECT_EQ(r.entry->sequence.seed, 2u);

  // A changed sweep file is refused: its runs would not match their plan.
  std::ofstream(sweep_file, std::ios::app) << "# edited\n";
  try {
    load_plan(dir, f.context);
    ADD_FAILURE() << "a changed sweep file was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("changed since it was planned"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace slamkit::sweep
