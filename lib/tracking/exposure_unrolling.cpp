#include "tracking/exposure_unrolling.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "features/frame_features.h"

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

UnrolledKeypoints unroll_exposure(const std::vector<cv::KeyPoint>& keypoints,
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
        timing.readout_s * ((double(keypoints[i].pt.y) + 0.5) / double(camera.height) - 0.5);
    const Motion row = motion_over(velocity, row_dt);
    const double z_seen = depths[i] > 0 ? double(depths[i]) : fallback_depth;
    const Eigen::Vector3d at_stamp = row.R * camera.back_project(undistorted[i], z_seen) + row.t;
    if (at_stamp.z() <= 0) continue;  // a degenerate velocity: leave the keypoint as seen
    out.undistorted[i] = camera.project(at_stamp);
    // The point in the depth image's camera, its depth there, and that depth back at the stamp.
    const Eigen::Vector3d in_depth = to_depth.R.transpose() * (at_stamp - to_depth.t);
    if (in_depth.z() <= 0) continue;
    const Eigen::Vector2d raw = camera.project_distorted(in_depth);
    const float z_depth = depth_at(depth_image, cv::KeyPoint(float(raw.x()), float(raw.y()), 1));
    if (z_depth <= 0) {  // none there (the reader zeroes depths out of the camera's range)
      out.depths[i] = 0;
      continue;
    }
    const Eigen::Vector3d measured = in_depth * (double(z_depth) / in_depth.z());
    out.depths[i] = float((to_depth.R * measured + to_depth.t).z());
  }
  return out;
}

}  // namespace slamkit
