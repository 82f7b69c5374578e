#pragma once
// The synthetic scenes, each built once per test binary (their textures take about a second).
#include <map>
#include <string>

#include "datasets/synth/room_layout.h"
#include "datasets/synth/trajectory_presets.h"

namespace slamkit::synth::test {

inline const SyntheticScene& shared_scene(Preset preset) {
  static std::map<std::string, SyntheticScene> scenes;
  const std::string name = preset_scene(preset);
  auto it = scenes.find(name);
  if (it == scenes.end()) it = scenes.emplace(name, make_named_scene(name)).first;
  return it->second;
}

inline const SyntheticScene& shared_room() { return shared_scene(Preset::kDesk); }

}  // namespace slamkit::synth::test
