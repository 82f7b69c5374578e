#pragma once
// Synthetic sequences for tests, rendered once per test binary run (the suite links
// slamkit_synth).
#include <filesystem>
#include <set>
#include <string>

#include "datasets/synth/room_layout.h"
#include "datasets/synth/sequence_writer.h"

namespace slamkit::test {

inline std::filesystem::path synthetic_sequence(synth::Preset preset, int frames) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "slamkit_tests" /
                                    "sequences" /
                                    (synth::preset_name(preset) + std::to_string(frames));
  static std::set<std::filesystem::path> rendered;
  if (!rendered.count(dir)) {
    std::filesystem::remove_all(dir);
    synth::SequenceSpec spec;
    spec.preset = preset;
    spec.frames = frames;
    spec.out = dir;
    synth::write_sequence(synth::make_furnished_room(), spec);
    rendered.insert(dir);
  }
  return dir;
}

}  // namespace slamkit::test
