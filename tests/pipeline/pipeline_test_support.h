#pragma once
// What the pipeline tests share: synthetic sequences rendered once per test binary run, the
// benchmark's ATE, and file comparison.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"
#include "eval/association.h"
#include "eval/ate.h"
#include "pipeline/batch_engine.h"

namespace slamkit::test {

// Rendered once per test process, into a folder of its own (ctest runs each test as its own
// process, several at once: a shared folder was removed under a reader), removed at exit.
inline std::filesystem::path synthetic_sequence(synth::Preset preset, int frames) {
  struct Rendered {
    std::set<std::filesystem::path> dirs;
    ~Rendered() {
      std::error_code ignored;
      for (const auto& dir : dirs) std::filesystem::remove_all(dir, ignored);
    }
  };
  static Rendered rendered;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "slamkit_tests" / "sequences" /
      (synth::preset_name(preset) + std::to_string(frames) + "-" + std::to_string(getpid()));
  if (!rendered.dirs.count(dir)) {
    std::filesystem::remove_all(dir);
    synth::SequenceSpec spec;
    spec.preset = preset;
    spec.frames = frames;
    spec.out = dir;
    synth::write_sequence(synth::make_furnished_room(), spec);
    rendered.dirs.insert(dir);
  }
  return dir;
}

// ATE RMSE (metres) as the benchmark computes it; every frame must have groundtruth.
inline double ate_rmse(const Trajectory& gt, const Trajectory& estimate) {
  EXPECT_EQ(eval::associate(gt, estimate, eval::AssociationOptions{}).size(), estimate.size())
      << "every frame must have groundtruth";
  return eval::ate_rmse(gt, estimate);
}

inline int count_lost(const RunResult& r) {
  int lost = 0;
  for (const TrackedFrame& f : r.frames) lost += f.lost;
  return lost;
}

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace slamkit::test
