// Suite files: what they hold once read, and errors that name the suite file and line.
#include "eval/regression/suite.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit::regress {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  fs::path dir = test::temp_dir("suite");
  SuiteContext context;
  Fixture() {
    // A sequence folder the reader accepts: lists naming existing files and a camera (images
    // are decoded only when a run reads them).
    const fs::path seq = dir / "data" / "seq_a";
    fs::create_directories(seq / "rgb");
    fs::create_directories(seq / "depth");
    std::ofstream(seq / "rgb" / "1.png") << "png";
    std::ofstream(seq / "depth" / "1.png") << "png";
    std::ofstream(seq / "rgb.txt") << "1.0 rgb/1.png\n";
    std::ofstream(seq / "depth.txt") << "1.0 depth/1.png\n";
    std::ofstream(seq / "calibration.yaml")
        << "fx: 525\nfy: 525\ncx: 319.5\ncy: 239.5\nwidth: 640\nheight: 480\n";
    context.data_dir = dir / "data";
    context.presets = {"desk", "loop"};
    context.tum_names = [] { return std::vector<std::string>{"freiburg1_desk"}; };
  }
  fs::path write(const std::string& text) const {
    const fs::path file = dir / "suite.yaml";
    std::ofstream(file) << text;
    return file;
  }
  // The message of the InputError loading `text` throws.
  std::string error(const std::string& text) const {
    try {
      load_suite(write(text), context);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST(Suite, ReadsEntriesSettingsTolerancesAndReferences) {
  Fixture f;
  const Suite suite = load_suite(f.write(R"(suite: mine
settings: {orb: {num_features: 800}}
tolerances:
  ate_rmse: {abs: 0.002}
entries:
  - name: a
    folder: seq_a
    depth_scale: 5208
    tolerances: {frames_lost: {abs: 2}}
    reference: {system: ORB-SLAM2 (paper), ate_rmse: 0.016}
  - name: b
    synthetic: {preset: loop, frames: 120, seed: 4}
    settings:
      orb:
        num_features: 200
  - name: c
    tum: freiburg1_desk
)"),
                                 f.context);
  EXPECT_EQ(suite.name, "mine");
  ASSERT_EQ(suite.entries.size(), 3u);
  const SuiteEntry& a = suite.entries[0];
  EXPECT_EQ(a.sequence.folder, f.dir / "data" / "seq_a");
  EXPECT_EQ(*a.sequence.depth_scale, 5208);
  EXPECT_EQ(a.settings.orb.num_features, 800);
  EXPECT_TRUE(a.has_overrides);
  EXPECT_EQ(a.tolerances.at("ate_rmse").abs, 0.002);
  EXPECT_EQ(a.tolerances.at("frames_lost").abs, 2);
  EXPECT_EQ(a.reference->ate_rmse, 0.016);
  const SuiteEntry& b = suite.entries[1];
  EXPECT_EQ(b.sequence.kind, SequenceSource::Kind::kSynthetic);
  EXPECT_EQ(b.sequence.describe(), "synthetic loop, 120 frames, seed 4");
  EXPECT_EQ(b.settings.orb.num_features, 200);  // the entry's wins over the suite's
  EXPECT_EQ(suite.entries[2].sequence.folder, f.dir / "data" / "rgbd_dataset_freiburg1_desk");
}

TEST(Suite, ErrorsNameTheFileAndLine) {
  Fixture f;
  const std::string file = (f.dir / "suite.yaml").string();
  const std::string head = "entries:\n  - name: a\n";
  EXPECT_EQ(f.error(head + "    folder: seq_a\n    colour: red\n"),
            file +
                ":4: unknown key 'colour' (expected name, folder, tum, synthetic, "
                "depth_scale, calibration, settings, tolerances, reference)");
  EXPECT_EQ(f.error(head + "    folder: nowhere\n"),
            file + ":3: sequence folder '" + (f.dir / "data" / "nowhere").string() + "' not found");
  EXPECT_EQ(f.error(head + "    tum: freiburg1_dsek\n"),
            file +
                ":3: unknown TUM RGB-D sequence 'freiburg1_dsek' "
                "(datasets/download_tum.sh --list shows the names)");
  EXPECT_EQ(f.error(head + "    synthetic: {preset: jerk, frames: 40}\n"),
            file + ":3: unknown synthetic preset 'jerk' (desk, loop)");
  // Inline settings are checked by the settings reader, at the suite's line.
  EXPECT_EQ(
      f.error(head + "    folder: seq_a\n    settings:\n      orb:\n        num_featurs: 5\n"),
      file + ":6: unknown setting 'orb.num_featurs'");
  EXPECT_NE(f.error(head + "    folder: seq_a\n    tolerances: {ate_rsme: {abs: 1}}\n")
                .find(file + ":4: unknown metric 'ate_rsme'"),
            std::string::npos);
  EXPECT_EQ(f.error(head + "    folder: seq_a\n  - name: a\n    folder: seq_a\n"),
            file + ":4: entry name 'a' is used twice");
  EXPECT_EQ(f.error(head + "    folder: seq_a\n    synthetic: {preset: desk, frames: 9}\n"),
            file + ":2: an entry needs exactly one of folder, tum and synthetic");
  f.context.data_dir.reset();
  EXPECT_EQ(f.error(head + "    folder: seq_a\n"),
            file +
                ":3: relative folder 'seq_a' needs the data folder: set SLAMKIT_DATA or "
                "pass --data");
}

}  // namespace
}  // namespace slamkit::regress
