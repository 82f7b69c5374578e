#include "datasets/synth/multi_room_layouts.h"

#include <algorithm>

#include "datasets/synth/layout_parts.h"
#include "datasets/synth/room_layout.h"

namespace slamkit::synth {
namespace {

using layout::box;
using layout::kCardboard;
using layout::kMetal;
using layout::kWood;
using layout::textured;

constexpr double kOpen = 1e9;  // a light zone's open side

const TextureStyle kEastWall = textured({165, 180, 200}, {70, 110, 170});

// The furnished room's pieces without its east poster (where the doorways are).
std::vector<Furniture> furnished_room_pieces(bool keep_east_wall_and_plain_corner) {
  std::vector<Furniture> pieces = furnished_room_description().furniture;
  for (Furniture& piece : pieces)
    piece.parts.erase(std::remove_if(piece.parts.begin(), piece.parts.end(),
                                     [](const BoxPart& p) { return p.bounds.min().x() > 2.45; }),
                      piece.parts.end());
  if (!keep_east_wall_and_plain_corner)
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(),
                                [](const Furniture& f) {
                                  return f.name == "shelf" || f.name == "plain corner";
                                }),
                 pieces.end());
  return pieces;
}

Furniture translated(Furniture piece, const Eigen::Vector3d& offset, int texture_twin) {
  for (BoxPart& part : piece.parts)
    part.bounds = Eigen::AlignedBox3d(part.bounds.min() + offset, part.bounds.max() + offset);
  piece.texture_twin = texture_twin;
  return piece;
}

// The second room of two_rooms, x 2.6..7.6: textured everywhere, unlike the first.
std::vector<Furniture> second_room_pieces() {
  const TextureStyle kTeak = textured({40, 80, 130}, {20, 40, 70});
  return {
      {"long table",
       {{box(4.2, 6.0, -0.5, 0.5, 0.70, 0.74), kTeak},
        {box(4.25, 4.33, -0.45, -0.37, 0.0, 0.70), kMetal},
        {box(5.87, 5.95, -0.45, -0.37, 0.0, 0.70), kMetal},
        {box(4.25, 4.33, 0.37, 0.45, 0.0, 0.70), kMetal},
        {box(5.87, 5.95, 0.37, 0.45, 0.0, 0.70), kMetal},
        {box(4.5, 4.9, -0.3, 0.1, 0.74, 0.95), kCardboard},
        {box(5.3, 5.7, 0.0, 0.3, 0.74, 0.80), textured({30, 30, 140}, {220, 220, 220})}}},
      {"bookcase",
       {{box(7.2, 7.6, -1.5, 1.5, 0.0, 2.0), textured({60, 120, 150}, {240, 230, 200})}}},
      {"sofa",
       {{box(3.5, 5.5, 1.3, 2.0, 0.0, 0.45), textured({120, 60, 90}, {200, 170, 190})},
        {box(3.5, 5.5, 1.8, 2.0, 0.45, 0.9), textured({120, 60, 90}, {200, 170, 190})}}},
      {"second room posters",
       {{box(3.5, 4.5, -2.0, -1.99, 1.1, 1.8), textured({20, 160, 220}, {30, 30, 30})},
        {box(5.5, 6.8, -2.0, -1.99, 1.0, 1.9), textured({210, 210, 240}, {160, 40, 40})},
        {box(6.0, 7.0, 1.99, 2.0, 1.2, 1.8), textured({90, 180, 90}, {250, 250, 250})}}},
      {"second room boxes",
       {{box(6.6, 7.1, -1.9, -1.4, 0.0, 0.5), kCardboard},
        {box(3.0, 3.3, -1.9, -1.6, 0.0, 0.6), textured({50, 110, 60}, {20, 50, 120})}}},
  };
}

}  // namespace

SceneDescription two_rooms_description() {
  SceneDescription d = furnished_room_description();
  d.name = "two_rooms";
  d.room = box(-2.5, 7.6, -2.0, 2.0, 0.0, 2.7);
  d.furniture = furnished_room_pieces(true);
  d.furniture.push_back(layout::partition(2.5, 2.6, d.room, -1.0, 0.1, kEastWall));
  for (Furniture& piece : second_room_pieces()) d.furniture.push_back(std::move(piece));
  d.lights = {layout::room_light(0.3, -0.3, -kOpen, kDoorwayX),
              layout::room_light(kSecondRoomCentre.x() + 0.3, -0.3, kDoorwayX, kOpen)};
  return d;
}

SceneDescription twin_rooms_description() {
  SceneDescription d = furnished_room_description();
  d.name = "twin_rooms";
  d.room = box(-5.05, 5.05, -2.0, 2.0, 0.0, 2.7);
  d.room_styles[0] = kEastWall;  // the far west wall, textured for tracking on the way
  d.furniture = {layout::partition(-0.05, 0.05, d.room, -0.9, 0.3, kEastWall)};

  // Each room's own walls and floor, as thin panels, so that both rooms carry the same ones.
  std::vector<Furniture> kit = {
      {"wall panels and floor",
       {{box(-2.5, 2.5, -2.0, -1.995, 0.0, 2.7), textured({200, 188, 168}, {130, 80, 50})},
        {box(-2.5, 2.5, 1.995, 2.0, 0.0, 2.7), textured({170, 200, 178}, {60, 120, 70})},
        {box(-2.5, 2.5, -2.0, 2.0, 0.0, 0.002), textured({85, 118, 150}, {40, 65, 100}, 0.4)}}}};
  for (Furniture& piece : furnished_room_pieces(false)) kit.push_back(std::move(piece));
  const int first = int(d.furniture.size());
  for (const Furniture& piece : kit) d.furniture.push_back(translated(piece, kFirstTwinCentre, -1));
  for (size_t k = 0; k < kit.size(); ++k)
    d.furniture.push_back(translated(kit[k], kFirstTwinCentre + kTwinOffset, first + int(k)));

  const double light_x = kFirstTwinCentre.x() + 0.3;
  d.lights = {layout::room_light(light_x, -0.3, -kOpen, 0.0),
              layout::room_light(light_x + kTwinOffset.x(), -0.3, 0.0, kOpen)};
  return d;
}

}  // namespace slamkit::synth
