#pragma once
// Pinhole camera with OpenCV's 5-parameter radial-tangential distortion (k1 k2 p1 p2 k3),
// the depth image's scale, the valid depth range and the exposure timing (rolling shutter,
// depth stamps).
#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slamkit {

struct Distortion {
  double k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0;
  bool is_zero() const { return k1 == 0 && k2 == 0 && p1 == 0 && p2 == 0 && k3 == 0; }
};

struct Camera {
  std::string name = "custom";
  double fx = 0, fy = 0, cx = 0, cy = 0;
  Distortion distortion;
  int width = 640, height = 480;
  double depth_scale = 5000.0;  // raw 16-bit depth units per metre
  double min_depth = 0.1;       // metres; depth outside [min, max] or 0 is invalid
  double max_depth = 8.0;
  // Rolling shutter: seconds from the first row's exposure to the last row's, the middle row
  // being at the frame's stamp; 0 for a global shutter (and when unknown).
  double readout_time = 0.0;
  // depth.txt's stamps are the instants the depth images were taken (a clock the recording
  // trusts). TUM's are not taken as such: reading the TUM pieces' depth at its stamps made them
  // worse (docs/measurement-log/experiments.md, exposure timing).
  bool exact_depth_stamps = false;

  // Pinhole projection of a camera-frame point (no distortion: keypoints are undistorted).
  Eigen::Vector2d project(const Eigen::Vector3d& p_c) const;
  // Inverse of project() for a pixel with depth z (metres).
  Eigen::Vector3d back_project(const Eigen::Vector2d& uv, double z) const;
  // Projection through the distortion model: where the lens puts the point in the raw image.
  Eigen::Vector2d project_distorted(const Eigen::Vector3d& p_c) const;
  // Raw (distorted) pixels to ideal pinhole pixels; OpenCV's undistortPoints does the work.
  std::vector<Eigen::Vector2d> undistort_pixels(const std::vector<Eigen::Vector2d>& raw) const;

  bool is_valid_depth(double z) const { return z >= min_depth && z <= max_depth; }
  bool contains(const Eigen::Vector2d& uv) const {
    return uv.x() >= 0 && uv.y() >= 0 && uv.x() <= width - 1 && uv.y() <= height - 1;
  }

  // The TUM RGB-D benchmark's cameras (docs/method.md#input).
  static Camera freiburg1();
  static Camera freiburg2();
  static Camera freiburg3();
  // The preset named by a sequence folder ("..._freiburg2_..."), if any.
  static std::optional<Camera> preset_for_sequence(const std::filesystem::path& folder);
};

}  // namespace slamkit
