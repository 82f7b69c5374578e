#pragma once
// Where a map point falls in a view, behind ORB-SLAM2's projection gates
// (docs/method.md#local-mapping-and-bundle-adjustment): in front of the camera and inside the
// image, its distance within the point's scale-valid range (0.8 x min to 1.2 x max), seen at
// most about 60 degrees off its mean viewing direction. Shared by duplicate fusion and the
// loop's neighbourhood search.
#include <Eigen/Geometry>
#include <optional>

#include "core/camera.h"
#include "map/map.h"

namespace slamkit {

struct PointProjection {
  Eigen::Vector3d p_c = Eigen::Vector3d::Zero();  // the point in the camera's frame
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();   // its pixel (undistorted)
  int octave = 0;                                 // the level it should be detected at
};

// The projection of `point` into a camera with pose T_c_w and centre `centre` (world), or
// nothing when a gate refuses it. Both are the caller's, computed once per view (a keyframe
// stores them). min_view_cos: the cosine of the largest angle to the point's mean viewing
// direction.
std::optional<PointProjection> project_point(const Map& map, const MapPoint& point,
                                             const Eigen::Isometry3d& T_c_w,
                                             const Eigen::Vector3d& centre, const Camera& camera,
                                             double min_view_cos);

}  // namespace slamkit
