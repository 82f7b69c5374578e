#pragma once
// The camera-frame points and normals of a depth image at each level of its pyramid: what
// dense point-to-plane alignment reads (SPEC section 2). Built once per frame, they serve as
// the current surface and again, one frame later, as the previous one.
#include <Eigen/Core>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "core/settings/tracking_settings.h"

namespace slamkit {

// One pixel: its point and unit normal in the camera frame. A pixel without a normal (no
// valid depth, a depth edge, a neighbour missing) has NaN in n and takes no part.
struct SurfacePoint {
  Eigen::Vector3f p, n;
  bool has_normal() const { return !std::isnan(n.z()); }
};

struct Surface {
  Camera camera;  // the level's pinhole camera (camera_at_level)
  int width = 0, height = 0;
  std::vector<SurfacePoint> pixels;  // row-major
  std::vector<int> with_normal;      // indices of the pixels that have a normal, ascending
  const SurfacePoint& at(int u, int v) const { return pixels[size_t(v) * size_t(width) + u]; }
};

// [0] at the depth image's resolution, [l] from the depth halved l times (depth_pyramid);
// settings.pyramid_levels levels.
using SurfacePyramid = std::vector<Surface>;

// depth: CV_32F metres in the pinhole geometry of `camera` (0 or outside the camera's valid
// range = none). The same output whatever the OpenMP thread count.
SurfacePyramid make_surface_pyramid(const cv::Mat& depth, const Camera& camera,
                                    const PointToPlaneSettings& settings);

}  // namespace slamkit
