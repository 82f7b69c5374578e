#include "map/point_projection.h"

namespace slamkit {

std::optional<PointProjection> project_point(const Map& map, const MapPoint& point,
                                             const Eigen::Isometry3d& T_c_w,
                                             const Eigen::Vector3d& centre, const Camera& camera,
                                             double min_view_cos) {
  PointProjection projection;
  projection.p_c = T_c_w * point.p_w;
  if (projection.p_c.z() <= 0) return std::nullopt;
  projection.uv = camera.project(projection.p_c);
  if (!camera.contains(projection.uv)) return std::nullopt;
  const Eigen::Vector3d ray = point.p_w - centre;
  const double distance = ray.norm();
  if (distance < 0.8 * point.min_distance || distance > 1.2 * point.max_distance)
    return std::nullopt;
  if (ray.dot(point.normal) < min_view_cos * distance * point.normal.norm()) return std::nullopt;
  projection.octave = map.predict_octave(point, distance);
  return projection;
}

}  // namespace slamkit
