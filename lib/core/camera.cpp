#include "core/camera.h"

#include <opencv2/calib3d.hpp>

namespace slamkit {

Eigen::Vector2d Camera::project(const Eigen::Vector3d& p_c) const {
  return {fx * p_c.x() / p_c.z() + cx, fy * p_c.y() / p_c.z() + cy};
}

Eigen::Vector3d Camera::back_project(const Eigen::Vector2d& uv, double z) const {
  return {(uv.x() - cx) * z / fx, (uv.y() - cy) * z / fy, z};
}

Eigen::Vector2d Camera::project_distorted(const Eigen::Vector3d& p_c) const {
  const double x = p_c.x() / p_c.z(), y = p_c.y() / p_c.z();
  const double r2 = x * x + y * y;
  const double radial = 1 + r2 * (distortion.k1 + r2 * (distortion.k2 + r2 * distortion.k3));
  const double xd = x * radial + 2 * distortion.p1 * x * y + distortion.p2 * (r2 + 2 * x * x);
  const double yd = y * radial + distortion.p1 * (r2 + 2 * y * y) + 2 * distortion.p2 * x * y;
  return {fx * xd + cx, fy * yd + cy};
}

std::vector<Eigen::Vector2d> Camera::undistort_pixels(
    const std::vector<Eigen::Vector2d>& raw) const {
  if (distortion.is_zero() || raw.empty()) return raw;
  std::vector<cv::Point2d> in(raw.size()), out;
  for (size_t i = 0; i < raw.size(); ++i) in[i] = {raw[i].x(), raw[i].y()};
  const cv::Matx33d K(fx, 0, cx, 0, fy, cy, 0, 0, 1);
  const cv::Matx<double, 1, 5> d(distortion.k1, distortion.k2, distortion.p1, distortion.p2,
                                 distortion.k3);
  // P = K maps the undistorted normalised points back to pixels. The iteration count is
  // raised from OpenCV's default 5: Freiburg 1's strong k3 needs more near the corners.
  cv::undistortPoints(in, out, K, d, cv::noArray(), K,
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 1e-12));
  std::vector<Eigen::Vector2d> result(out.size());
  for (size_t i = 0; i < out.size(); ++i) result[i] = {out[i].x, out[i].y};
  return result;
}

namespace {

// Freiburg 1 and 2 are Kinects (v1), whose colour camera has a rolling shutter. TUM publishes no
// readout time; 30 ms (about a frame period at 30 Hz) is the kinect sensor model's assumption
// (docs/sensor.md), and Kerl et al. (ICCV 2015) simulate such a camera with 28 ms. With frame
// refinement every value from 20 to 33 ms lowers the ATE of fr1/desk and of fr2/desk at both
// depth scales; fr2/desk's at 5208 by a quarter or more (docs/measurement-log/experiments.md).
constexpr double kKinectReadoutTime = 0.030;

}  // namespace

Camera Camera::freiburg1() {
  Camera c;
  c.name = "freiburg1";
  c.fx = 517.3, c.fy = 516.5, c.cx = 318.6, c.cy = 255.3;
  c.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
  c.readout_time = kKinectReadoutTime;
  return c;
}

Camera Camera::freiburg2() {
  Camera c;
  c.name = "freiburg2";
  c.fx = 520.9, c.fy = 521.0, c.cx = 325.1, c.cy = 249.7;
  c.distortion = {0.2312, -0.7849, -0.0033, -0.0001, 0.9172};
  c.readout_time = kKinectReadoutTime;
  return c;
}

Camera Camera::freiburg3() {
  Camera c;
  c.name = "freiburg3";
  c.fx = 535.4, c.fy = 539.2, c.cx = 320.1, c.cy = 247.6;
  return c;
}

std::optional<Camera> Camera::preset_for_sequence(const std::filesystem::path& folder) {
  // The folder's own name decides, not its parents' (lexically_normal drops a trailing '/').
  std::filesystem::path normal = folder.lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();
  const std::string name = normal.filename().string();
  if (name.find("freiburg1") != std::string::npos) return freiburg1();
  if (name.find("freiburg2") != std::string::npos) return freiburg2();
  if (name.find("freiburg3") != std::string::npos) return freiburg3();
  return std::nullopt;
}

}  // namespace slamkit
