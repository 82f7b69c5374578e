#pragma once
// Camera calibration files (YAML) for sequences that are not one of the Freiburg presets:
//   fx: 525.0  fy: 525.0  cx: 319.5  cy: 239.5       (required)
//   k1 k2 p1 p2 k3: 0                                  (optional, OpenCV's model)
//   width: 640  height: 480  depth_scale: 5000  min_depth: 0.1  max_depth: 8.0  name: ...
#include <filesystem>

#include "core/camera.h"

namespace slamkit {

Camera read_camera_yaml(const std::filesystem::path& path);
void write_camera_yaml(const std::filesystem::path& path, const Camera& camera);

}  // namespace slamkit
