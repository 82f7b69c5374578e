#include "datasets/synth/room_layout.h"

#include "core/error.h"
#include "datasets/synth/layout_parts.h"
#include "datasets/synth/multi_room_layouts.h"

namespace slamkit::synth {
using layout::box;
using layout::kCardboard;
using layout::kMetal;
using layout::kPlainRug;
using layout::kPlainWall;
using layout::kWood;
using layout::textured;

SceneDescription furnished_room_description() {
  SceneDescription d;
  d.room = box(-2.5, 2.5, -2.0, 2.0, 0.0, 2.7);
  d.room_styles = {
      kPlainWall,                                       // west, x = -2.5
      textured({165, 180, 200}, {70, 110, 170}),        // east
      textured({200, 188, 168}, {130, 80, 50}),         // south
      textured({170, 200, 178}, {60, 120, 70}),         // north
      textured({85, 118, 150}, {40, 65, 100}, 0.4),     // floor tiles
      textured({212, 212, 210}, {150, 150, 155}, 0.6),  // ceiling panels
  };
  d.name = "furnished_room";
  d.lights = {{Eigen::Vector3d(0.3, -0.3, 2.45)}};

  d.furniture.push_back(
      {"desk",
       {{box(-0.7, 0.7, -0.4, 0.4, 0.72, 0.76), kWood},
        {box(-0.67, -0.62, -0.37, -0.32, 0.0, 0.72), kMetal},
        {box(0.62, 0.67, -0.37, -0.32, 0.0, 0.72), kMetal},
        {box(-0.67, -0.62, 0.32, 0.37, 0.0, 0.72), kMetal},
        {box(0.62, 0.67, 0.32, 0.37, 0.0, 0.72), kMetal},
        {box(-0.3, 0.3, 0.18, 0.22, 0.86, 1.2), textured({50, 45, 40}, {210, 160, 90})},
        {box(-0.05, 0.05, 0.22, 0.27, 0.76, 0.86), kMetal},
        {box(-0.22, 0.22, -0.2, -0.05, 0.76, 0.785), textured({40, 40, 40}, {200, 200, 200})},
        {box(0.35, 0.6, -0.3, -0.1, 0.76, 0.8), textured({60, 60, 170}, {200, 200, 220})},
        {box(0.37, 0.58, -0.28, -0.12, 0.8, 0.85), textured({150, 90, 40}, {230, 220, 200})},
        {box(-0.6, -0.4, -0.25, 0.0, 0.76, 0.92), kCardboard},
        {box(0.25, 0.32, 0.05, 0.12, 0.76, 0.86), textured({220, 220, 225}, {40, 40, 200})}}});
  d.furniture.push_back(
      {"tall cabinet",
       {{box(2.05, 2.5, -1.9, -1.1, 0.0, 1.9), textured({150, 150, 175}, {60, 60, 100})},
        {box(2.03, 2.05, -1.88, -1.52, 0.05, 1.85), textured({170, 165, 185}, {50, 50, 70})},
        {box(2.03, 2.05, -1.48, -1.12, 0.05, 1.85), textured({170, 165, 185}, {50, 50, 70})}}});
  d.furniture.push_back(
      {"sideboard",
       {{box(-1.2, 0.2, 1.55, 2.0, 0.0, 0.8), textured({95, 135, 175}, {40, 70, 110})},
        {box(-0.9, -0.6, 1.65, 1.9, 0.8, 1.0), kCardboard},
        {box(-0.1, 0.1, 1.7, 1.9, 0.8, 1.05), textured({60, 140, 60}, {30, 60, 140})}}});
  d.furniture.push_back(
      {"shelf",
       {{box(2.2, 2.5, 0.2, 1.4, 1.2, 1.23), kWood},
        {box(2.2, 2.5, 0.2, 1.4, 1.6, 1.63), kWood},
        {box(2.25, 2.45, 0.25, 0.5, 1.23, 1.45), textured({40, 40, 150}, {220, 220, 220})},
        {box(2.25, 2.45, 0.55, 0.7, 1.23, 1.5), textured({140, 60, 30}, {200, 230, 240})},
        {box(2.28, 2.45, 0.9, 1.3, 1.63, 1.8), textured({50, 150, 200}, {20, 20, 20})}}});
  d.furniture.push_back({"floor boxes",
                         {{box(1.2, 1.6, -1.95, -1.55, 0.0, 0.4), kCardboard},
                          {box(1.25, 1.5, -1.9, -1.65, 0.4, 0.6), kCardboard},
                          {box(1.5, 1.95, 1.3, 1.9, 0.0, 0.35), kCardboard},
                          {box(-2.0, -1.5, -1.9, -1.5, 0.0, 0.5), kCardboard}}});
  d.furniture.push_back(
      {"posters",
       {{box(-1.2, -0.2, -2.0, -1.99, 1.2, 1.9), textured({230, 230, 230}, {30, 30, 160})},
        {box(0.6, 1.5, 1.99, 2.0, 1.1, 1.8), textured({40, 40, 40}, {90, 200, 230})},
        {box(2.49, 2.5, -0.8, 0.0, 1.0, 1.7), textured({200, 120, 60}, {240, 240, 240})}}});
  // Plain geometry in front of the plain wall: with the wall and the floor rug it gives
  // surfaces facing +x, +y and +z, so depth alone constrains all six degrees of freedom.
  d.furniture.push_back({"plain corner",
                         {{box(-2.5, -2.2, -0.2, 0.25, 0.0, 2.7), kPlainWall},
                          {box(-2.5, -2.1, 0.25, 1.1, 0.0, 0.55), kPlainWall},
                          {box(-2.5, -1.5, -0.6, 1.6, 0.0, 0.004), kPlainRug}}});
  return d;
}

SyntheticScene make_furnished_room() { return SyntheticScene(furnished_room_description()); }

SyntheticScene make_named_scene(const std::string& name) {
  if (name == "furnished_room") return make_furnished_room();
  if (name == "two_rooms") return SyntheticScene(two_rooms_description());
  if (name == "twin_rooms") return SyntheticScene(twin_rooms_description());
  throw InputError("unknown scene '" + name + "' (known: furnished_room, two_rooms, twin_rooms)");
}

}  // namespace slamkit::synth
