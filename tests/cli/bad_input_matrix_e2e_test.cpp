// The bad-input matrix (README, "Bad input"): for every command and every class of bad input
// that command can meet, slamkit exits with code 2 and prints one line on stderr that names the
// file at fault, with its line where the fault is on one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <functional>
#include <map>
#include <opencv2/core.hpp>

#include "io/png_file.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string input_class;  // a row of the README's table
  std::string args;         // after `slamkit`
  fs::path file;            // the file the error line must name
  int line = 0;             // and its line, when there is one
};

void expect_one_line_naming_the_file(const Case& c) {
  SCOPED_TRACE(c.input_class + ": slamkit " + c.args);
  const test::SlamkitResult r = test::run_slamkit_apart(c.args);
  EXPECT_EQ(r.code, 2) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "more than one line:\n" << r.err;
  const std::string where =
      c.file.string() + (c.line > 0 ? ":" + std::to_string(c.line) + ":" : "");
  EXPECT_NE(r.err.find(where), std::string::npos) << "does not name " << where << ":\n" << r.err;
}

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A folder where a file is expected: unreadable as a file, also for root (who reads any file
// whatever its permissions, as CI does).
void replace_by_folder(const fs::path& file) {
  fs::remove(file);
  fs::create_directories(file);
}

// A TUM-layout sequence of three 64x48 frames with its calibration and groundtruth, and copies
// of it each broken in one way.
class Sequences {
 public:
  Sequences() : root_(test::temp_dir("bad_input")) {
    const fs::path good = root_ / "good";
    write(good / "calibration.yaml", "fx: 50\nfy: 50\ncx: 31.5\ncy: 23.5\nwidth: 64\nheight: 48\n");
    std::string rgb = "# colour images\n", depth = "# depth images\n";
    for (const char* stamp : kStamps) {
      write_frame(good, stamp, cv::Size(64, 48), CV_16UC1);
      rgb += std::string(stamp) + " rgb/" + stamp + ".png\n";
      depth += std::string(stamp) + " depth/" + stamp + ".png\n";
    }
    write(good / "rgb.txt", rgb);
    write(good / "depth.txt", depth);
    write(good / "groundtruth.txt", groundtruth(0));
  }

  fs::path good() const { return root_ / "good"; }
  const fs::path& root() const { return root_; }
  static std::string first_frame() { return std::string(kStamps[0]) + ".png"; }

  // A copy of the good sequence, changed by `change`.
  fs::path variant(const std::string& name, const std::function<void(const fs::path&)>& change) {
    const fs::path folder = root_ / name;
    fs::remove_all(folder);
    fs::copy(good(), folder, fs::copy_options::recursive);
    change(folder);
    return folder;
  }

  // Poses every 10 ms around the frames, `shift` seconds later.
  static std::string groundtruth(double shift) {
    std::string text = "# timestamp tx ty tz qx qy qz qw\n";
    for (int k = 0; k <= 20; ++k)
      text += std::to_string(0.95 + 0.01 * k + shift) + " 0 0 " + std::to_string(0.001 * k) +
              " 0 0 0 1\n";
    return text;
  }

  static void write_frame(const fs::path& folder, const std::string& stamp, cv::Size size,
                          int depth_type) {
    cv::Mat rgb(size, CV_8UC3), depth(size, depth_type, cv::Scalar(5000));
    cv::randu(rgb, 0, 255);
    fs::create_directories(folder / "rgb");
    fs::create_directories(folder / "depth");
    write_png(folder / "rgb" / (stamp + ".png"), rgb);
    write_png(folder / "depth" / (stamp + ".png"), depth);
  }

 private:
  static constexpr const char* kStamps[] = {"1.000000", "1.033333", "1.066667"};
  fs::path root_;
};

// The classes every command that reads a sequence meets (track, run, info).
std::vector<Case> sequence_cases(Sequences& s, const std::string& command,
                                 const std::string& options) {
  const auto args = [&](const fs::path& folder) {
    return command + " " + folder.string() + options;
  };
  const std::string frame = Sequences::first_frame();
  std::vector<Case> cases = {
      {"missing file", args(s.variant("no_list", [](auto f) { fs::remove(f / "rgb.txt"); })),
       s.root() / "no_list" / "rgb.txt"},
      {"missing file", args(s.root() / "no_such_folder"), s.root() / "no_such_folder"},
      {"unreadable file",
       args(s.variant("list_folder", [](auto f) { replace_by_folder(f / "rgb.txt"); })),
       s.root() / "list_folder" / "rgb.txt"},
      {"malformed line",
       args(s.variant("short_line",
                      [](auto f) {
                        write(f / "rgb.txt", "# colour\n1.000000 rgb/1.000000.png\n1.033333\n");
                      })),
       s.root() / "short_line" / "rgb.txt", 3},
      {"wrong image type",
       args(s.variant(
           "depth_8bit",
           [](auto f) { Sequences::write_frame(f, "1.000000", cv::Size(64, 48), CV_8UC1); })),
       s.root() / "depth_8bit" / "depth" / frame},
      {"wrong image size",
       args(s.variant(
           "small_frame",
           [](auto f) { Sequences::write_frame(f, "1.000000", cv::Size(32, 24), CV_16UC1); })),
       s.root() / "small_frame" / "rgb" / frame},
      {"empty depth", args(s.variant("empty_png", [&](auto f) { write(f / "depth" / frame, ""); })),
       s.root() / "empty_png" / "depth" / frame},
      {"empty depth",
       args(s.variant("empty_list", [](auto f) { write(f / "depth.txt", "# depth\n"); })),
       s.root() / "empty_list" / "depth.txt"},
      {"non-finite value",
       args(s.variant("nan_stamp",
                      [](auto f) { write(f / "rgb.txt", "# colour\nnan rgb/1.000000.png\n"); })),
       s.root() / "nan_stamp" / "rgb.txt", 2},
      {"non-finite value",
       args(s.variant("nan_fx",
                      [](auto f) {
                        write(f / "calibration.yaml", "fx: .nan\nfy: 50\ncx: 31.5\ncy: 23.5\n");
                      })),
       s.root() / "nan_fx" / "calibration.yaml", 1},
      {"no groundtruth overlap",
       args(s.variant("late_groundtruth",
                      [](auto f) { write(f / "groundtruth.txt", Sequences::groundtruth(1000)); })),
       s.root() / "late_groundtruth" / "groundtruth.txt"},
  };
  if (geteuid() != 0)  // root reads a file whatever its permissions
    cases.push_back(
        {"unreadable file",
         args(s.variant("no_permission",
                        [](auto f) { fs::permissions(f / "rgb.txt", fs::perms::none); })),
         s.root() / "no_permission" / "rgb.txt"});
  return cases;
}

// track and run: the sequence's classes, and --settings with a key that is not a setting.
void expect_run_commands_refuse_bad_input(const std::string& command) {
  Sequences s;
  const std::string options = " --no-eval --threads 1 --out " + (s.root() / "out").string();
  for (const Case& c : sequence_cases(s, command, options)) expect_one_line_naming_the_file(c);
  const fs::path settings = s.root() / "typo.yaml";
  write(settings, "orb:\n  num_feature: 500\n");
  expect_one_line_naming_the_file(
      {"unknown setting",
       command + " " + s.good().string() + options + " --settings " + settings.string(),
       settings, 2});
}

TEST(BadInputMatrix, TheGoodSequenceIsRead) {
  Sequences s;
  std::string output;
  EXPECT_EQ(test::run_slamkit("info " + s.good().string(), &output), 0) << output;
}

TEST(BadInputMatrix, Track) { expect_run_commands_refuse_bad_input("track"); }

TEST(BadInputMatrix, Run) { expect_run_commands_refuse_bad_input("run"); }

TEST(BadInputMatrix, Info) {
  Sequences s;
  for (const Case& c : sequence_cases(s, "info", "")) expect_one_line_naming_the_file(c);
}

TEST(BadInputMatrix, EvalAteRpeAll) {
  Sequences s;
  const fs::path gt = s.good() / "groundtruth.txt";
  const fs::path est = s.root() / "est.txt", bad = s.root() / "bad.txt";
  write(est, Sequences::groundtruth(0));
  const fs::path folder = s.root() / "a_folder";
  fs::create_directories(folder);
  for (const char* metric : {"ate", "rpe", "all"}) {
    const auto args = [&](const fs::path& g, const fs::path& e) {
      return std::string("eval ") + metric + " " + g.string() + " " + e.string() + " --no-plot";
    };
    expect_one_line_naming_the_file(
        {"missing file", args(s.root() / "none.txt", est), s.root() / "none.txt"});
    expect_one_line_naming_the_file({"unreadable file", args(gt, folder), folder});
    write(bad, "1.0 0 0 0 0 0 0 1\n1.01 0 0 0 0 0 1\n");
    expect_one_line_naming_the_file({"malformed line", args(gt, bad), bad, 2});
    write(bad, "1.0 nan 0 0 0 0 0 1\n1.01 0 inf 0 0 0 0 1\n");
    expect_one_line_naming_the_file({"non-finite value", args(gt, bad), bad});
    write(bad, Sequences::groundtruth(1000));
    expect_one_line_naming_the_file({"no groundtruth overlap", args(gt, bad), bad});
  }
}

TEST(BadInputMatrix, EvalCompare) {
  Sequences s;
  const auto args = [&](const fs::path& run) {
    return "eval compare " + run.string() + " --out " + (s.root() / "compare").string();
  };
  const fs::path run = s.root() / "run";
  expect_one_line_naming_the_file(
      {"missing file", args(s.root() / "no_run"), s.root() / "no_run" / "metrics.json"});
  replace_by_folder(run / "metrics.json");
  expect_one_line_naming_the_file({"unreadable file", args(run), run / "metrics.json"});
  fs::remove_all(run);
  write(run / "metrics.json", "{\"ate\": {\"rmse\": 0.1,\n");
  expect_one_line_naming_the_file({"malformed line", args(run), run / "metrics.json"});
  write(run / "metrics.json", "{\"ate\": {\"rmse\": \"nan\"}}\n");
  expect_one_line_naming_the_file({"non-finite value", args(run), run / "metrics.json"});
  write(run / "run.json", "{\"status\": \"interrupted\", \"signal\": 15}\n");
  expect_one_line_naming_the_file({"interrupted run", args(run), run / "run.json"});
}

TEST(BadInputMatrix, Regress) {
  Sequences s;
  const fs::path suite = s.root() / "suite.yaml";
  const std::string args = "regress " + suite.string() + " --no-download --out " +
                           (s.root() / "regress").string() + " --baselines " +
                           (s.root() / "baselines").string();
  const auto entry = [](const std::string& sequence) {
    return "entries:\n  - name: a\n    " + sequence + "\n";
  };
  const std::string desk = entry("synthetic: {preset: desk, frames: 10}");
  const auto expect = [&](const std::string& input_class, const std::string& text,
                          const fs::path& file, int line) {
    write(suite, text);
    expect_one_line_naming_the_file({input_class, args, file, line});
  };
  expect_one_line_naming_the_file({"missing file",
                                   "regress " + (s.root() / "none.yaml").string() + " --out x",
                                   s.root() / "none.yaml"});
  replace_by_folder(s.root() / "folder.yaml");
  expect_one_line_naming_the_file({"unreadable file",
                                   "regress " + (s.root() / "folder.yaml").string() + " --out x",
                                   s.root() / "folder.yaml"});
  expect("malformed line", entry("synthetic: {preset: desk, frames: [}"), suite, 3);
  expect("non-finite value", "tolerances:\n  ate_rmse: {abs: .nan}\n" + desk, suite, 2);
  expect("unknown setting", desk + "    settings: {orb: {num_feature: 500}}\n", suite, 4);
  const fs::path late = s.variant("late_groundtruth", [](auto f) {
    write(f / "groundtruth.txt", Sequences::groundtruth(1000));
  });
  expect("no groundtruth overlap", entry("folder: " + late.string()), late / "groundtruth.txt", 0);
  const fs::path broken = s.variant("short_line", [](auto f) {
    write(f / "rgb.txt", "# colour\n1.000000 rgb/1.000000.png\n1.033333\n");
  });
  expect("malformed line", entry("folder: " + broken.string()), broken / "rgb.txt", 3);
  write(s.root() / "baselines" / "a.json", "{\"format\": 2, \"metrics\": {}}\n");
  expect("unsupported version", desk, s.root() / "baselines" / "a.json", 0);
}

TEST(BadInputMatrix, Synth) {
  Sequences s;
  const std::string out = " --out " + (s.root() / "synth").string();
  expect_one_line_naming_the_file({"malformed value", "synth --preset spiral" + out, "--preset"});
  expect_one_line_naming_the_file({"malformed value", "synth --frames 1" + out, "--frames"});
  write(s.root() / "a_file", "");
  expect_one_line_naming_the_file({"unwritable output",
                                   "synth --frames 2 --out " + (s.root() / "a_file" / "x").string(),
                                   s.root() / "a_file" / "x"});
}

TEST(BadInputMatrix, MapEval) {
  Sequences s;
  const fs::path seq = s.variant("synthetic", [](auto f) {
    write(f / "synthetic.yaml", "scene: furnished_room\npreset: desk\nframes: 3\nseed: 1\n");
  });
  const fs::path map = s.root() / "map.ply", est = s.root() / "est.txt";
  const std::string xyz_header =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  write(map, xyz_header + "0 0 1\n0 1 1\n");
  const auto args = [&](const fs::path& m, const fs::path& sequence, const std::string& more) {
    return "map-eval " + m.string() + " " + sequence.string() + more;
  };
  expect_one_line_naming_the_file(
      {"missing file", args(s.root() / "none.ply", seq, ""), s.root() / "none.ply"});
  replace_by_folder(s.root() / "folder.ply");
  expect_one_line_naming_the_file(
      {"unreadable file", args(s.root() / "folder.ply", seq, ""), s.root() / "folder.ply"});
  write(s.root() / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 9\nend_header\n1 2\n");
  expect_one_line_naming_the_file(
      {"malformed line", args(s.root() / "bad.ply", seq, ""), s.root() / "bad.ply", 3});
  write(s.root() / "nan.ply", xyz_header + "0 0 1\nnan 1 1\n");
  expect_one_line_naming_the_file(
      {"non-finite value", args(s.root() / "nan.ply", seq, ""), s.root() / "nan.ply"});
  write(s.root() / "origin.ply", xyz_header + "0 0 0\n0 0 0\n");
  expect_one_line_naming_the_file(
      {"wrong input", args(s.root() / "origin.ply", seq, ""), s.root() / "origin.ply"});
  const fs::path bad_info = s.variant("bad_info", [](auto f) {
    write(f / "synthetic.yaml", "scene: furnished_room\npreset: [desk\n");
  });
  expect_one_line_naming_the_file(
      {"malformed line", args(map, bad_info, ""), bad_info / "synthetic.yaml", 3});
  expect_one_line_naming_the_file({"wrong input type", args(map, s.good(), ""), s.good()});
  write(est, "1.0 nan 0 0 0 0 0 1\n");
  expect_one_line_naming_the_file(
      {"non-finite value", args(map, seq, " --trajectory " + est.string()), est});
  write(est, Sequences::groundtruth(1000));
  expect_one_line_naming_the_file(
      {"no groundtruth overlap", args(map, seq, " --trajectory " + est.string()), est});
}

TEST(BadInputMatrix, VocabAndRunVocabulary) {
  Sequences s;
  const fs::path folder = s.root() / "a_folder.voc", text = s.root() / "text.voc";
  const fs::path future = s.root() / "future.voc";
  replace_by_folder(folder);
  write(text, "10 5 0 0\n0 1 2 3\n");
  // Our binary header: magic, then version 99 (little-endian), then a node count.
  std::ofstream(future, std::ios::binary) << std::string("SKVOCAB\0", 8)
                                          << std::string("\x63\0\0\0\0\0\0\0\0\0\0\0", 12);
  expect_one_line_naming_the_file(
      {"missing file", "vocab info " + (s.root() / "none.voc").string(), s.root() / "none.voc"});
  expect_one_line_naming_the_file({"unreadable file", "vocab info " + folder.string(), folder});
  expect_one_line_naming_the_file({"malformed line", "vocab info " + text.string(), text, 2});
  expect_one_line_naming_the_file({"unsupported version", "vocab info " + future.string(), future});
  expect_one_line_naming_the_file(
      {"unsupported version",
       "run " + s.good().string() + " --out " + (s.root() / "out").string() + " --vocabulary " +
           future.string(),
       future});
}

// Every file of a folder with its size: what a command must leave alone.
std::map<std::string, uintmax_t> files_of(const fs::path& folder) {
  std::map<std::string, uintmax_t> files;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    files[e.path().string()] = e.is_regular_file() ? e.file_size() : 0;
  return files;
}

// An output path that exists as a file, or lies under one, is named in slamkit's words.
TEST(BadInputMatrix, OutputPathThatIsAFile) {
  Sequences s;
  const fs::path file = s.root() / "a_file";
  write(file, "");
  const std::string seq = s.good().string() + " ", gt = (s.good() / "groundtruth.txt").string();
  for (const fs::path& out : {file, file / "x"}) {
    const std::string o = " --out " + out.string();
    for (const std::string& args :
         {"run " + seq + o, "track " + seq + o, "synth --frames 2" + o,
          "regress " + (s.root() / "suite.yaml").string() + o, "eval ate " + gt + " " + gt + o,
          "eval all " + gt + " " + gt + o, "eval compare " + s.root().string() + o,
          "sweep plan " + (s.root() / "sweep.yaml").string() + o})
      expect_one_line_naming_the_file({"output path under a file", args, "--out " + out.string()});
  }
  expect_one_line_naming_the_file({"output path under a file",
                                   "eval ate " + gt + " " + gt + " --plot " + file.string(),
                                   "--plot " + file.string()});
  // vocab train writes a file: one under a file, or a folder there, is refused.
  expect_one_line_naming_the_file({"output path under a file",
                                   "vocab train " + seq + "--out " + (file / "x").string(),
                                   "--out " + (file / "x").string()});
  expect_one_line_naming_the_file({"output path that is a folder",
                                   "vocab train " + seq + "--out " + s.root().string(),
                                   "--out " + s.root().string()});
  const test::SlamkitResult r = test::run_slamkit_apart("run " + seq + "--out " + file.string());
  EXPECT_EQ(r.err, "slamkit: error: --out " + file.string() + ": exists and is not a folder\n");
}

// Run files among the sequence's own are refused, however the folder is spelled.
TEST(BadInputMatrix, OutputInsideTheSequence) {
  Sequences s;
  const fs::path good = s.good(), link = s.root() / "link";
  fs::create_directory_symlink(good, link);
  const auto before = files_of(good);
  struct Spelling {
    fs::path sequence, out;
  };
  const std::vector<Spelling> spellings = {
      {good, good},
      {good, good / "out"},
      {good, good / "rgb" / ".." / "out"},
      {good, link / "out"},
      {link, good / "out"},
      {s.root() / "x" / ".." / "good", good / "deeper" / "out"},
  };
  for (const Spelling& sp : spellings)
    for (const char* command : {"run", "track"}) {
      const std::string args = std::string(command) + " " + sp.sequence.string() +
                               " --no-eval --threads 1 --out " + sp.out.string();
      expect_one_line_naming_the_file(
          {"output inside the sequence", args, "--out " + sp.out.string()});
      const test::SlamkitResult r = test::run_slamkit_apart(args);
      EXPECT_NE(r.err.find("inside the input sequence " + sp.sequence.string() + " "),
                std::string::npos)
          << r.err;
    }
  expect_one_line_naming_the_file(
      {"output inside the sequence",
       "vocab train " + good.string() + " --out " + (good / "words.voc").string(),
       "--out " + (good / "words.voc").string()});
  EXPECT_EQ(files_of(good), before);

  // A sibling whose name starts with the sequence's is outside it; the flag allows inside.
  std::string output;
  EXPECT_EQ(test::run_slamkit(
                "track " + good.string() + " --no-eval --threads 1 --out " + good.string() + "_out",
                &output),
            0)
      << output;
  EXPECT_EQ(test::run_slamkit("track " + good.string() + " --no-eval --threads 1 --out " +
                                  (good / "out").string() + " --allow-out-in-sequence",
                              &output),
            0)
      << output;
  EXPECT_TRUE(fs::exists(good / "out" / "trajectory.txt"));
}

}  // namespace
}  // namespace slamkit
