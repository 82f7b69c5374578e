#include "map/point_projection.h"

namespace slamkit {

std::optional<PointProjection> project_point(const Map& map, const MapPoint& point,
                                             const Eigen::Isometry3d& T_w_c, const Camera& camera,
                                             double min_view_cos) {
  PointProjection projection;
  projection.p_c = T_w_c.inverse() * point.p_w;
  if (projection.p_c.z() <= 0) return std::nullopt;
  projection.uv = camera.project(projection.p_c);
  if (!camera.contains(projection.uv)) return std::nullopt;
  const Eigen::Vector3d ray = point.p_w - T_w_c.translation();
  const double distance = ray.norm();
  if (distance < 0.8 * point.min_distance || distance > 1.2 * point.max_distance)
    return std::nullopt;
  if (ray.dot(point.normal) < min_view_cos * distance * point.normal.norm()) return std::nullopt;
  projection.octave = map.predict_octave(point, distance);
  return projection;
}

}  // namespace slamkit
