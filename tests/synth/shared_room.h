#pragma once
// The furnished room, built once per test binary (its textures take about a second).
#include "datasets/synth/room_layout.h"

namespace slamkit::synth::test {

inline const SyntheticScene& shared_room() {
  static const SyntheticScene scene = make_furnished_room();
  return scene;
}

}  // namespace slamkit::synth::test
