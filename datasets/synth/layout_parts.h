#pragma once
// The building blocks the room layouts share: boxes, texture styles, common materials.
#include <Eigen/Geometry>

#include "datasets/synth/scene.h"

namespace slamkit::synth::layout {

inline Eigen::AlignedBox3d box(double x0, double x1, double y0, double y1, double z0, double z1) {
  return {Eigen::Vector3d(x0, y0, z0), Eigen::Vector3d(x1, y1, z1)};
}

inline TextureStyle textured(cv::Scalar base, cv::Scalar accent, double tile_size_m = 0) {
  return {base, accent, false, tile_size_m};
}

// Colours are BGR.
inline const TextureStyle kWood = textured({70, 115, 165}, {35, 60, 100});
inline const TextureStyle kMetal = textured({75, 75, 80}, {160, 160, 165});
inline const TextureStyle kCardboard = textured({105, 150, 190}, {40, 70, 110});
inline const TextureStyle kPlainWall = TextureStyle::plain_colour({188, 198, 204});
inline const TextureStyle kPlainRug = TextureStyle::plain_colour({150, 160, 168});

// A wall between x0 and x1 across the room's y span, with a doorway 2.1 m high over
// door_y0..door_y1: two wall parts and a lintel.
inline Furniture partition(double x0, double x1, const Eigen::AlignedBox3d& room, double door_y0,
                           double door_y1, const TextureStyle& style) {
  const double y0 = room.min().y(), y1 = room.max().y(), height = room.max().z();
  return {"partition with a doorway",
          {{box(x0, x1, y0, door_y0, 0, height), style},
           {box(x0, x1, door_y1, y1, 0, height), style},
           {box(x0, x1, door_y0, door_y1, 2.1, height), style}}};
}

// A light over (x, y) that lights only the surfaces with x in [zone_x0, zone_x1].
inline Light room_light(double x, double y, double zone_x0, double zone_x1) {
  return {Eigen::Vector3d(x, y, 2.45), box(zone_x0, zone_x1, -1e9, 1e9, -1e9, 1e9)};
}

}  // namespace slamkit::synth::layout
