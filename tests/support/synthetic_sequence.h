#pragma once
// Synthetic sequences for tests (the suite links slamkit_synth), rendered once per test
// process into a folder of its own and removed at exit: ctest runs each test as its own
// process, several at once, and a shared folder was removed under a reader.
#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>
#include <system_error>

#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"

namespace slamkit::test {

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
    synth::write_sequence(synth::make_named_scene(synth::preset_scene(preset)), spec);
    rendered.dirs.insert(dir);
  }
  return dir;
}

}  // namespace slamkit::test
