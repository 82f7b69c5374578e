#pragma once
// Photometric residuals for dense alignment: the grey level of each of the current frame's
// edge pixels against the previous image where the pixel's point lands, linearised in the
// same 6-vector as point-to-plane (point_to_plane_equations.h), so that both terms add up in
// one Gauss-Newton step. Hand-written because it feeds the paper's hand-written step: OpenCV's
// RgbdICPOdometry combines the two terms only inside an odometry of its own, with its own
// pyramid, association and solver.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/tracking_settings.h"
#include "tracking/surface_pyramid.h"

namespace slamkit {

// One level of a frame's grey image in pinhole geometry, with its gradient (grey levels per
// pixel, Sobel) and the pixels whose gradient reaches photometric_min_gradient and whose
// depth gives a normal (a depth edge's pixels would pair foreground with background).
struct GreyLevel {
  cv::Mat grey, gx, gy;    // CV_32F
  std::vector<int> edges;  // Surface::index of the edge pixels
};
using GreyPyramid = std::vector<GreyLevel>;

// grey: CV_8U in the pinhole geometry of `surfaces` (one level each, halved as the depth is,
// by 2x2 block means).
GreyPyramid make_grey_pyramid(const cv::Mat& grey, const SurfacePyramid& surfaces,
                              const PointToPlaneSettings& settings);

struct PhotometricEquations {
  Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();  // sum w h h^T
  Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::Zero();  // sum w r h
  double sum_sq = 0;                                                    // sum w r^2
  int count = 0;  // edge pixels that landed inside the previous image
};

// At T_prev_curr: per current edge pixel with point p moved into the previous camera,
// r = I_prev(pi(p)) - I_curr (bilinear), h = (a x p, a) with a = grad I_prev J_pi(p), the
// derivative of r under the alignment's increment; w is the Huber weight of r. Unweighted by
// photometric_weight. Single-threaded, so the same sums at any thread count.
PhotometricEquations photometric_equations(const GreyLevel& prev, const GreyLevel& curr,
                                           const Surface& curr_surface,
                                           const Eigen::Isometry3d& T_prev_curr,
                                           const PointToPlaneSettings& settings);

}  // namespace slamkit
