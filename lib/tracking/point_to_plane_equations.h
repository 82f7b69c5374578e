#pragma once
// The normal equations of one Gauss-Newton step of dense point-to-plane alignment
// (docs/method.md#matching-and-pose): projective association of every current point with the
// previous surface, and the sums of the linearised cost's rows.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/settings/tracking_settings.h"
#include "tracking/surface_pyramid.h"

namespace slamkit {

struct PointToPlaneEquations {
  Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();  // sum h h^T
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();  // sum m h
  double sum_sq = 0;                                                    // sum m^2
  double sum_p2 = 0;  // sum |p|^2, the scale of the rotation columns
  int count = 0;      // pairs
};

// At T_prev_curr (current camera to previous camera), for two surfaces of the same pyramid
// level, the pairs whose previous pixel lies in box (pixels of that level). Per pair, with p
// the current point moved into the previous camera, q and N the previous point and normal:
// m = (p - q).N and h = (N x p, N) (h^T = N^T G with G = [[p]x | I]). The same sums, bit for
// bit, whatever the OpenMP thread count.
PointToPlaneEquations point_to_plane_equations(const Surface& prev, const Surface& curr,
                                               const cv::Rect& box,
                                               const Eigen::Isometry3d& T_prev_curr,
                                               const PointToPlaneSettings& settings);

}  // namespace slamkit
