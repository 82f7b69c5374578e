#pragma once
// The synthetic world: a room (the inside of a box: floor, ceiling, four walls) furnished
// with axis-aligned boxes, every face carrying its own texture. Ray casting and distances
// are analytic and written by hand: none of our libraries ray-casts a handful of boxes, and
// exact answers are the point (tests compare rendered depth against them).
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "datasets/synth/procedural_texture.h"
#include "datasets/synth/texture.h"

namespace slamkit::synth {

struct BoxPart {
  Eigen::AlignedBox3d bounds;
  TextureStyle style;
};

// A piece of furniture: its name documents the layout, its parts are what rays hit.
struct Furniture {
  std::string name;
  std::vector<BoxPart> parts;
  // Index of an earlier piece with parts of the same sizes (a translated copy) whose
  // textures this one repeats, so that the two look the same; -1: textures of its own.
  int texture_twin = -1;
};

// A point light. There are no shadows, so a light would shine through a wall into the next
// room: it lights only the surfaces inside its zone.
struct Light {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::AlignedBox3d zone{Eigen::Vector3d::Constant(-1e9), Eigen::Vector3d::Constant(1e9)};
};

// Faces of a box are indexed 2 * axis + side (side 0 at the min corner): -x +x -y +y -z +z.
struct SceneDescription {
  std::string name;                         // as synthetic.yaml names it (room_layout.h)
  Eigen::AlignedBox3d room;                 // its inside is the free space
  std::array<TextureStyle, 6> room_styles;  // walls -x +x -y +y, floor (-z), ceiling (+z)
  std::vector<Furniture> furniture;
  std::vector<Light> lights;  // a surface takes the first light whose zone holds it
  double texels_per_metre = 320;
  uint64_t texture_seed = 7;
};

struct SurfaceHit {
  double t = 0;                                      // point = origin + t * direction
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // world frame
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit, facing the ray's origin
  int surface = -1;                                  // index of the face hit
};

class SyntheticScene {
 public:
  // Generates every face's texture (OpenMP over faces; the result does not depend on it).
  // Throws std::invalid_argument for a texture twin that is not an earlier piece of the
  // same part sizes, or for no light.
  explicit SyntheticScene(SceneDescription description);

  // The first surface along origin + t * direction (t > 0); `direction` need not be a unit
  // vector, t is in its units. Rays that leave the room through a gap would return nullopt,
  // but the room is closed, so a ray cast from inside always hits something.
  std::optional<SurfaceHit> cast_ray(const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& direction) const;
  // The same, testing only the box parts listed (see parts_in_cone).
  std::optional<SurfaceHit> cast_ray(const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& direction,
                                     const std::vector<int>& parts) const;

  // The box parts a ray from `origin` inside the convex cone spanned by `edges` (in order
  // round the cone) may hit. Renderers ask once per tile of pixels, so that each ray tests
  // only the few parts its tile can see: the whole acceleration structure there is.
  std::vector<int> parts_in_cone(const Eigen::Vector3d& origin,
                                 const std::array<Eigen::Vector3d, 4>& edges) const;

  // Positive in free space, negative inside furniture or beyond the room's walls.
  double signed_distance(const Eigen::Vector3d& p_w) const;
  // Unsigned distance to the nearest face of the room or of any box part.
  double distance_to_surface(const Eigen::Vector3d& p_w) const;

  // Lit colour (BGR, 0..255, may exceed 255) at a hit, textures prefiltered for a camera
  // pixel covering `footprint_m` metres. Lambertian: the same from every viewpoint.
  Eigen::Vector3f colour(const SurfaceHit& hit, double footprint_m) const;

  const SceneDescription& description() const { return description_; }

 private:
  struct Box {
    Eigen::Vector3d min, max;
    int first_surface;
  };

 public:
  // How a face maps world points to texture coordinates (metres, v pointing down on walls).
  struct FaceFrame {
    int u_axis, v_axis;
    double u0, v0, v_sign;
    double width_m, height_m;
  };

 private:
  SceneDescription description_;
  std::vector<Box> boxes_;
  std::vector<int> all_parts_;          // 0 .. boxes_.size() - 1
  std::vector<FaceFrame> face_frames_;  // per surface
  std::vector<Texture> textures_;       // per surface
};

}  // namespace slamkit::synth
