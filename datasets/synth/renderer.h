#pragma once
// Ray casts one RGB-D frame of the scene: one ray through each pixel centre (so that
// back-projecting a depth pixel with Camera::back_project lands on the surface it saw),
// colour from the prefiltered textures, then the sensor model's noise.
#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "datasets/synth/scene.h"
#include "datasets/synth/sensor_model.h"

namespace slamkit::synth {

struct RenderedFrame {
  cv::Mat bgr;    // CV_8UC3
  cv::Mat depth;  // CV_16UC1, camera z in 1/camera.depth_scale metres, 0 where missing
};

// The view from T_w_c (camera: x right, y down, z forward). The camera's distortion is
// ignored (the synthetic camera has none). Noise depends only on (seed, frame_index, pixel),
// never on which thread renders what.
RenderedFrame render_frame(const SyntheticScene& scene, const Camera& camera,
                           const Eigen::Isometry3d& T_w_c, const SensorModel& sensor, uint64_t seed,
                           uint64_t frame_index);

}  // namespace slamkit::synth
