#include "datasets/synth/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "datasets/synth/counter_rng.h"

namespace slamkit::synth {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Lighting: ambient plus one point light whose strength falls off over a few metres.
constexpr float kAmbient = 0.55f, kDiffuse = 0.75f;
constexpr double kFalloffSquared = 4.0 * 4.0;

// Where the ray (origin, 1/direction) enters and leaves an axis-aligned box, and through
// which axis' faces. NaN from a ray lying in a face plane compares false and drops out.
struct Slab {
  double t_near = -kInf, t_far = kInf;
  int axis_near = 0, axis_far = 0;
};

inline Slab slab(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector3d& o,
                 const Eigen::Vector3d& inv) {
  Slab s;
  for (int k = 0; k < 3; ++k) {
    double t0 = (lo[k] - o[k]) * inv[k], t1 = (hi[k] - o[k]) * inv[k];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > s.t_near) s.t_near = t0, s.axis_near = k;
    if (t1 < s.t_far) s.t_far = t1, s.axis_far = k;
  }
  return s;
}

// Signed distance to a box's surface: negative inside.
double box_distance(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                    const Eigen::Vector3d& p) {
  const Eigen::Vector3d q = (p - 0.5 * (lo + hi)).cwiseAbs() - 0.5 * (hi - lo);
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

// Texture frame of face (axis, side) of a box. Vertical faces run u horizontally and v down
// from the top edge, so patterns stand upright; horizontal faces use x and y.
SyntheticScene::FaceFrame face_frame(const Eigen::AlignedBox3d& box, int axis) {
  const Eigen::Vector3d size = box.sizes();
  if (axis == 2) return {0, 1, box.min().x(), box.min().y(), 1.0, size.x(), size.y()};
  const int u = axis == 0 ? 1 : 0;
  return {u, 2, box.min()[u], box.max().z(), -1.0, size[u], size.z()};
}

// A twin repeats its original's textures part by part: the parts must match in size.
void check_twin(const Furniture& piece, const std::vector<Furniture>& furniture) {
  if (piece.texture_twin < 0) return;
  const auto index = size_t(piece.texture_twin);
  const bool earlier = index < furniture.size() && &furniture[index] < &piece;
  const auto same_sizes = [&](const Furniture& original) {
    if (original.parts.size() != piece.parts.size()) return false;
    for (size_t k = 0; k < piece.parts.size(); ++k)
      if (!original.parts[k].bounds.sizes().isApprox(piece.parts[k].bounds.sizes(), 1e-9))
        return false;
    return true;
  };
  if (!earlier || !same_sizes(furniture[index]) || furniture[index].texture_twin >= 0)
    throw std::invalid_argument("scene: '" + piece.name +
                                "' is no twin of an earlier original piece of its shape");
}

}  // namespace

SyntheticScene::SyntheticScene(SceneDescription description)
    : description_(std::move(description)) {
  if (description_.lights.empty()) throw std::invalid_argument("scene: no light");
  std::vector<TextureStyle> styles;
  std::vector<int> texture_ids;  // a face's texture seed; a twin's face takes its original's
  const auto add_faces = [&](const Eigen::AlignedBox3d& box, int first_texture_id,
                             const auto& style_of_face) {
    for (int face = 0; face < 6; ++face) {
      face_frames_.push_back(face_frame(box, face / 2));
      styles.push_back(style_of_face(face));
      texture_ids.push_back(first_texture_id + face);
    }
  };
  add_faces(description_.room, 0, [&](int face) { return description_.room_styles[face]; });
  std::vector<int> first_face_of_piece;
  for (const Furniture& piece : description_.furniture) {
    check_twin(piece, description_.furniture);
    first_face_of_piece.push_back(int(face_frames_.size()));
    const int first_texture_id = piece.texture_twin < 0 ? int(face_frames_.size())
                                                        : first_face_of_piece[piece.texture_twin];
    for (size_t k = 0; k < piece.parts.size(); ++k) {
      const BoxPart& part = piece.parts[k];
      all_parts_.push_back(int(boxes_.size()));
      boxes_.push_back({part.bounds.min(), part.bounds.max(), int(face_frames_.size())});
      add_faces(part.bounds, first_texture_id + 6 * int(k), [&](int) { return part.style; });
    }
  }

  std::vector<cv::Mat> images(face_frames_.size());
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < int(images.size()); ++i)
    images[i] = make_procedural_image(face_frames_[i].width_m, face_frames_[i].height_m,
                                      description_.texels_per_metre, styles[i],
                                      mix64(description_.texture_seed) + uint64_t(texture_ids[i]));
  for (const cv::Mat& image : images) textures_.emplace_back(image, description_.texels_per_metre);
}

std::vector<int> SyntheticScene::parts_in_cone(const Eigen::Vector3d& origin,
                                               const std::array<Eigen::Vector3d, 4>& edges) const {
  const Eigen::Vector3d axis = edges[0] + edges[1] + edges[2] + edges[3];
  std::array<Eigen::Vector3d, 4> normals;  // of the cone's side planes, pointing inwards
  for (int k = 0; k < 4; ++k) {
    normals[k] = edges[k].cross(edges[(k + 1) % 4]);
    if (normals[k].dot(axis) < 0) normals[k] = -normals[k];
  }
  std::vector<int> parts;
  for (int b = 0; b < int(boxes_.size()); ++b) {
    // A millimetre of margin keeps rounding from culling a part a ray just grazes.
    const Eigen::Vector3d lo = boxes_[b].min.array() - 1e-3 - origin.array();
    const Eigen::Vector3d hi = boxes_[b].max.array() + 1e-3 - origin.array();
    const auto outside = [&](const Eigen::Vector3d& n) {
      // The corner farthest along n: if even it is behind the plane, the whole box is.
      const Eigen::Vector3d far(n.x() > 0 ? hi.x() : lo.x(), n.y() > 0 ? hi.y() : lo.y(),
                                n.z() > 0 ? hi.z() : lo.z());
      return n.dot(far) < 0;
    };
    if (std::none_of(normals.begin(), normals.end(), outside)) parts.push_back(b);
  }
  return parts;
}

std::optional<SurfaceHit> SyntheticScene::cast_ray(const Eigen::Vector3d& origin,
                                                   const Eigen::Vector3d& direction) const {
  return cast_ray(origin, direction, all_parts_);
}

std::optional<SurfaceHit> SyntheticScene::cast_ray(const Eigen::Vector3d& origin,
                                                   const Eigen::Vector3d& direction,
                                                   const std::vector<int>& parts) const {
  const Eigen::Vector3d inv = direction.cwiseInverse();
  // The room is seen from inside: the hit is where the ray leaves it.
  const Slab room = slab(description_.room.min(), description_.room.max(), origin, inv);
  if (!(room.t_far > 0) || room.t_near > room.t_far) return std::nullopt;
  double best_t = room.t_far;
  int best_axis = room.axis_far;
  int best_surface = 2 * room.axis_far + (direction[room.axis_far] > 0 ? 1 : 0);

  for (const int b : parts) {
    const Box& box = boxes_[b];
    const Slab s = slab(box.min, box.max, origin, inv);
    // Entering from outside only (t_near > 0): a camera never sits inside furniture.
    if (s.t_near > s.t_far || s.t_near <= 0 || s.t_near >= best_t) continue;
    best_t = s.t_near;
    best_axis = s.axis_near;
    best_surface = box.first_surface + 2 * s.axis_near + (direction[s.axis_near] > 0 ? 0 : 1);
  }

  SurfaceHit hit;
  hit.t = best_t;
  hit.point = origin + best_t * direction;
  hit.normal[best_axis] = direction[best_axis] > 0 ? -1.0 : 1.0;
  hit.surface = best_surface;
  return hit;
}

double SyntheticScene::signed_distance(const Eigen::Vector3d& p_w) const {
  double d = -box_distance(description_.room.min(), description_.room.max(), p_w);
  for (const Box& box : boxes_) d = std::min(d, box_distance(box.min, box.max, p_w));
  return d;
}

double SyntheticScene::distance_to_surface(const Eigen::Vector3d& p_w) const {
  double d = std::abs(box_distance(description_.room.min(), description_.room.max(), p_w));
  for (const Box& box : boxes_) d = std::min(d, std::abs(box_distance(box.min, box.max, p_w)));
  return d;
}

Eigen::Vector3f SyntheticScene::colour(const SurfaceHit& hit, double footprint_m) const {
  const FaceFrame& f = face_frames_[hit.surface];
  const double u = hit.point[f.u_axis] - f.u0;
  const double v = f.v_sign * (hit.point[f.v_axis] - f.v0);
  const Eigen::Vector3f albedo = textures_[hit.surface].sample(u, v, footprint_m);

  const std::vector<Light>& lights = description_.lights;
  const auto lit = std::find_if(lights.begin(), lights.end(),
                                [&](const Light& light) { return light.zone.contains(hit.point); });
  const Eigen::Vector3d to_light = (lit == lights.end() ? lights[0] : *lit).position - hit.point;
  const double d2 = to_light.squaredNorm();
  const double lambert = std::max(0.0, hit.normal.dot(to_light) / std::sqrt(d2));
  return albedo * (kAmbient + kDiffuse * float(lambert / (1.0 + d2 / kFalloffSquared)));
}

}  // namespace slamkit::synth
