#pragma once
// Moves a frame's keypoints to where a global-shutter camera would have seen them at the colour
// stamp, and reads their depth at the depth image's own instant (docs/method.md#exposure-timing).
// Real RGB-D cameras take neither image at the colour stamp: a rolling shutter exposes row v at
// stamp + readout * ((v + 0.5) / height - 0.5), and the depth image has its own stamp (fr1's
// lead or lag the colour by up to 20 ms). Under a 30 deg/s pan a 30 ms readout skews the image
// by about a degree top to bottom, which the pose solvers, all global-shutter, turn into
// orientation error. Given the camera's velocity the skew and the lag can be undone point by
// point, with no change to the solvers: each keypoint's observation is moved back along the
// motion to the stamp.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"

namespace slamkit {

struct ExposureTiming {
  double readout_s = 0;       // rolling shutter: first row's exposure to the last row's
  double depth_offset_s = 0;  // the depth image's instant minus the colour stamp
  bool is_instant() const { return readout_s == 0 && depth_offset_s == 0; }
};

// The camera's velocity at the stamp, both in the camera's own frame: over a short dt the pose
// moves as T_w_c(t + dt) = T_w_c(t) [exp([angular dt]x) | linear dt].
struct CameraVelocity {
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();  // rad/s
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();   // m/s
};

struct UnrolledKeypoints {
  std::vector<Eigen::Vector2d> undistorted;  // pinhole pixels at the colour stamp
  std::vector<float> depths;                 // metres along those rays, 0 = none
};

// `keypoints` are at their raw (distorted) pixels, whose rows are the sensor's and set the
// exposure time; `undistorted` and `depths` are their pinhole pixels and the depths read at the
// raw pixel. A keypoint whose depth pixel, found again at the depth image's instant, holds no valid
// depth keeps its pixel and loses its depth. With no motion or instant timing the input comes
// back unchanged.
UnrolledKeypoints unroll_exposure(const std::vector<cv::KeyPoint>& keypoints,
                                  const std::vector<Eigen::Vector2d>& undistorted,
                                  const std::vector<float>& depths, const cv::Mat& depth_image,
                                  const Camera& camera, const ExposureTiming& timing,
                                  const CameraVelocity& velocity);

}  // namespace slamkit
