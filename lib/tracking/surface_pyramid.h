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

// One row per pixel: x y z of the point, then nx ny nz of its unit normal, in the camera
// frame. A column per coordinate, so that whole columns go through SIMD.
using SurfaceColumns = Eigen::Matrix<float, Eigen::Dynamic, 6>;

struct Surface {
  Camera camera;  // the level's pinhole camera (camera_at_level)
  int width = 0, height = 0;
  // Every pixel, row-major. A pixel without a normal (no valid depth, a depth edge, a
  // neighbour missing) has NaN in its normal and takes no part; without a valid depth its
  // point is NaN too.
  SurfaceColumns pixels;
  int index(int u, int v) const { return v * width + u; }
  bool has_normal(int i) const { return !std::isnan(pixels(i, 5)); }
};

// [0] at the depth image's resolution, [l] from the depth halved l times (depth_pyramid);
// settings.pyramid_levels levels.
using SurfacePyramid = std::vector<Surface>;

// depth: CV_32F metres in the pinhole geometry of `camera` (0 or outside the camera's valid
// range = none). The same output whatever the OpenMP thread count.
SurfacePyramid make_surface_pyramid(const cv::Mat& depth, const Camera& camera,
                                    const PointToPlaneSettings& settings);

}  // namespace slamkit
