#pragma once
// The one furnished room every preset films: 5 x 4 x 2.7 m, z up, floor at z = 0, a desk in
// the middle, cabinets, a sideboard, a shelf, posters and boxes, all textured, except the
// west wall (x = -2.5) with a pillar and a bench in front of it, all plain, for the
// `lowtexture` preset.
#include <Eigen/Core>
#include <string>

#include "datasets/synth/scene.h"

namespace slamkit::synth {

// Landmarks the trajectory presets aim at (world frame, metres).
inline const Eigen::Vector3d kDeskTopCentre{0.0, 0.0, 0.76};
// Where the plain pillar, the plain bench and the plain west wall meet.
inline const Eigen::Vector3d kPlainCorner{-2.5, 0.25, 0.55};

SceneDescription furnished_room_description();

// The room with its textures generated (about a second; build it once and share it).
SyntheticScene make_furnished_room();

// A scene by its description's name: furnished_room, or two_rooms and twin_rooms
// (multi_room_layouts.h). Throws InputError for another name.
SyntheticScene make_named_scene(const std::string& name);

}  // namespace slamkit::synth
