#include "tracking/exposure_unrolling.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace slamkit {
namespace {

// The camera's motion over dt from the stamp: a point at x in the camera at t + dt is at
// R x + t in the camera at the stamp.
struct Motion {
  Eigen::Matrix3d R;
  Eigen::Vector3d t;
};

Motion motion_over(const CameraVelocity& v, double dt) {
  const Eigen::Vector3d rotation = v.angular * dt;
  const double angle = rotation.norm();
  Motion m;
  m.R = angle > 0 ? Eigen::AngleAxisd(angle, rotation / angle).toRotationMatrix()
                  : Eigen::Matrix3d::Identity();
  m.t = v.linear * dt;
  return m;
}

// Depth of the nearest raw pixel, 0 outside the image or where the image holds none.
float depth_at_raw(const cv::Mat& depth, const Eigen::Vector2d& raw) {
  const int u = int(std::lround(raw.x())), v = int(std::lround(raw.y()));
  if (u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) return 0.0f;
  const float z = depth.at<float>(v, u);
  return std::isfinite(z) && z > 0 ? z : 0.0f;
}

// Where a keypoint without depth is assumed to lie, for the translation's small share of its
// motion: the frame's median keypoint depth.
double typical_depth(const std::vector<float>& depths) {
  std::vector<float> valid;
  for (float z : depths)
    if (z > 0) valid.push_back(z);
  if (valid.empty()) return 2.0;
  std::nth_element(valid.begin(), valid.begin() + long(valid.size() / 2), valid.end());
  return valid[valid.size() / 2];
}

}  // namespace

UnrolledKeypoints unroll_exposure(const std::vector<float>& raw_rows,
                                  const std::vector<Eigen::Vector2d>& undistorted,
                                  const std::vector<float>& depths, const cv::Mat& depth_image,
                                  const Camera& camera, const ExposureTiming& timing,
                                  const CameraVelocity& velocity) {
  UnrolledKeypoints out{undistorted, depths};
  if (timing.is_instant()) return out;
  const double fallback_depth = typical_depth(depths);
  // The depth image's camera: a point x at the stamp is at R_d^T (x - t_d) in it.
  const Motion to_depth = motion_over(velocity, timing.depth_offset_s);
  for (size_t i = 0; i < undistorted.size(); ++i) {
    const double row_dt =
        timing.readout_s * ((double(raw_rows[i]) + 0.5) / double(camera.height) - 0.5);
    const Motion row = motion_over(velocity, row_dt);
    const double z_seen = depths[i] > 0 ? double(depths[i]) : fallback_depth;
    const Eigen::Vector3d at_stamp = row.R * camera.back_project(undistorted[i], z_seen) + row.t;
    if (at_stamp.z() <= 0) continue;  // a degenerate velocity: leave the keypoint as seen
    out.undistorted[i] = camera.project(at_stamp);
    // The point in the depth image's camera, its depth there, and that depth back at the stamp.
    const Eigen::Vector3d in_depth = to_depth.R.transpose() * (at_stamp - to_depth.t);
    if (in_depth.z() <= 0) continue;
    const float z_depth = depth_at_raw(depth_image, camera.project_distorted(in_depth));
    if (z_depth <= 0) {  // the reader zeroes depths out of the camera's range
      out.depths[i] = 0;
      continue;
    }
    const Eigen::Vector3d measured = in_depth * (double(z_depth) / in_depth.z());
    out.depths[i] = float((to_depth.R * measured + to_depth.t).z());
  }
  return out;
}

}  // namespace slamkit
