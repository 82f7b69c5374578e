#pragma once
// The camera-frame points and normals of a depth image at each level of its pyramid: what
// dense point-to-plane alignment reads (docs/method.md#matching-and-pose). Built once per
// frame, they serve as the current surface and again, one frame later, as the previous one.
#include <Eigen/Core>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "core/settings/tracking_settings.h"

namespace slamkit {

// One row per pixel: z of the point, then nx ny nz of its unit normal, in the camera frame.
// A column per quantity, so that whole columns go through SIMD. x and y are not stored but
// computed where they are read (Surface::point): a third less to write per frame and to read
// per alignment iteration.
using SurfaceColumns = Eigen::Matrix<float, Eigen::Dynamic, 4>;

struct Surface {
  Camera camera;  // the level's pinhole camera (camera_at_level)
  int width = 0, height = 0;
  // Every pixel, row-major. A pixel without a normal (no valid depth, a depth edge, a
  // neighbour missing) has NaN in its normal and takes no part; without a valid depth its
  // z is NaN too.
  SurfaceColumns pixels;
  // Back-projection: the point of pixel (u, v) is (x_factors[u] z, y_factors[v] z, z).
  std::vector<float> x_factors, y_factors;
  int index(int u, int v) const { return v * width + u; }
  bool has_normal(int i) const { return !std::isnan(pixels(i, 3)); }
  Eigen::Vector3f point(int i) const {
    const float z = pixels(i, 0);
    return {x_factors[size_t(i % width)] * z, y_factors[size_t(i / width)] * z, z};
  }
  Eigen::Vector3f normal(int i) const { return pixels.row(i).tail<3>().transpose(); }
};

// [0] at the depth image's resolution, [l] from the depth halved l times (depth_pyramid);
// settings.pyramid_levels levels.
using SurfacePyramid = std::vector<Surface>;

// depth: CV_32F metres in the pinhole geometry of `camera` (0 or outside the camera's valid
// range = none). The same output whatever the OpenMP thread count.
SurfacePyramid make_surface_pyramid(const cv::Mat& depth, const Camera& camera,
                                    const PointToPlaneSettings& settings);

}  // namespace slamkit
