#pragma once
// Scenes of more than one room, for the loop-closing presets (trajectory_presets.h).
#include <Eigen/Core>

#include "datasets/synth/scene.h"

namespace slamkit::synth {

// two_rooms (preset `long`): the furnished room (room_layout.h) with its east wall turned
// into a partition with a doorway (y -1.0..0.1, where the east poster hung), and a second,
// differently furnished room east of it (x 2.6..7.6): a long table, a bookcase, a sofa.
SceneDescription two_rooms_description();
inline const Eigen::Vector3d kSecondRoomCentre{5.1, 0.0, 0.0};
inline constexpr double kDoorwayX = 2.55, kDoorwayY = -0.45;  // the doorway's centre

// twin_rooms (preset `lookalike`): two identical rooms side by side (x -5.05..-0.05 and
// 0.05..5.05), joined by a doorway in the partition between them (y -0.9..0.3). Each holds
// the furnished room's desk, cabinet, sideboard, boxes and posters on the same textured
// wall panels and floor, with its own light in the same place: a view in one room looks
// like the same view kTwinOffset further east, in the other.
SceneDescription twin_rooms_description();
inline const Eigen::Vector3d kTwinOffset{5.1, 0.0, 0.0};
inline const Eigen::Vector3d kFirstTwinCentre{-2.55, 0.0, 0.0};  // the west room's centre
inline constexpr double kTwinDoorwayY = -0.3;                      // the doorway's centre

}  // namespace slamkit::synth
