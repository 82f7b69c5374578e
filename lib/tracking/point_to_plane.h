#pragma once
// Dense point-to-plane alignment of two depth images (docs/method.md#matching-and-pose), the
// paper's fallback when there are too few 3D pairs for the closed form.
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/settings/tracking_settings.h"
#include "tracking/photometric_equations.h"
#include "tracking/surface_pyramid.h"

namespace slamkit {

enum class DenseAlignStatus {
  kConverged,
  kNotConverged,           // still moving after the last iteration: tracking has failed
  kTooFewCorrespondences,  // fewer than settings.min_correspondences pairs on some level
  kIllConditioned,         // the geometry leaves a direction free (e.g. one plane in view)
};

struct DenseAlignment {
  DenseAlignStatus status = DenseAlignStatus::kNotConverged;
  // The estimate reached (the guess when no step was taken).
  Eigen::Isometry3d T_prev_curr = Eigen::Isometry3d::Identity();
  int num_correspondences = 0;  // pairs in the last iteration
  double min_eigenvalue = 0;    // conditioning of the last normal matrix (see settings)
  double rmse = 0;              // point-to-plane residual of the last iteration, metres
  int iterations = 0;           // Gauss-Newton steps over all levels
  // The last increment was below the thresholds. With kIllConditioned the free directions
  // kept the guess and the constrained ones converged: a usable, partly predicted pose.
  bool converged = false;
  bool ok() const { return status == DenseAlignStatus::kConverged; }
};

// Refines T_prev_curr (maps current-camera points into the previous camera) from an initial
// guess, coarse to fine over the surfaces of the two frames (make_surface_pyramid, with the
// same settings). Only previous-frame pixels inside box_prev (level-0 pixels; the bounding box
// of the matched keypoints) are used; an empty box means the whole image. With both frames'
// grey pyramids (make_grey_pyramid) and a photometric_weight, each step also weighs the
// current edge pixels' grey levels (photometric_equations). Deterministic whatever the OpenMP
// thread count.
DenseAlignment point_to_plane(const SurfacePyramid& prev, const SurfacePyramid& curr,
                              const Eigen::Isometry3d& T_prev_curr_guess, const cv::Rect& box_prev,
                              const PointToPlaneSettings& settings,
                              const GreyPyramid* prev_grey = nullptr,
                              const GreyPyramid* curr_grey = nullptr);

}  // namespace slamkit
