#pragma once
// Ray casts the kinect sensor's frames (kinect_sensor.h): the colour image integrated over
// its exposure and read out row band by row band, and the depth image from the IR camera with
// the projector's shadow, lateral and axial noise, disparity quantisation and depth edges.
// Noise depends only on (seed, frame index, pixel), never on which thread renders what.
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "datasets/synth/kinect_sensor.h"
#include "datasets/synth/scene.h"

namespace slamkit::synth {

// T_w_c of the colour camera at time t (seconds from the first frame).
using PoseAt = std::function<Eigen::Isometry3d(double t)>;

// The colour camera's ray directions (camera frame, z = 1) through every pixel centre: through
// the lens distortion when that effect is on (the camera's undistort_pixels does the work).
std::vector<Eigen::Vector3d> colour_pixel_rays(const Camera& camera, const KinectSettings& s);

// The camera with the distortion and rolling-shutter readout the colour image has, and depth
// stamps that are exact (calibration.yaml carries them).
Camera kinect_colour_camera(const Camera& camera, const KinectSettings& s);

// The number of exposure sub-frames for a frame at t: one per blur_step_px the scene moves in
// the image during the exposure (probed at nine pixels), 1 when still or motion_blur is off.
int exposure_subframes(const SyntheticScene& scene, const Camera& camera, const PoseAt& pose_at,
                       const KinectSettings& s, double t);

// The auto-exposure gain at t: a slow seeded drift of its logarithm (1 when off).
double exposure_gain(const KinectSettings& s, uint64_t seed, double t);

// CV_8UC3 colour frame `frame_index` stamped t: row v's exposure is centred at
// t + readout_s * ((v + 0.5) / height - 0.5) (rolling shutter; one pose per 16-row band).
cv::Mat render_kinect_colour(const SyntheticScene& scene, const Camera& camera,
                             const std::vector<Eigen::Vector3d>& rays, const PoseAt& pose_at,
                             const KinectSettings& s, uint64_t seed, uint64_t frame_index,
                             double t);

// The depth camera's pose given the colour camera's: offset by the misregistration.
Eigen::Isometry3d depth_camera_pose(const Eigen::Isometry3d& T_w_colour, const KinectSettings& s);

// CV_16UC1 depth frame `depth_index` seen from T_w_d (the IR camera, pinhole `camera`), in
// 1/camera.depth_scale metres, 0 where missing.
cv::Mat render_kinect_depth(const SyntheticScene& scene, const Camera& camera,
                            const Eigen::Isometry3d& T_w_d, const KinectSettings& s, uint64_t seed,
                            uint64_t depth_index);

}  // namespace slamkit::synth
