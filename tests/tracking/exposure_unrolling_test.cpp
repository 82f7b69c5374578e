#include "tracking/exposure_unrolling.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace slamkit {
namespace {

Camera test_camera() {
  Camera c;
  c.fx = c.fy = 525;
  c.cx = 319.5;
  c.cy = 239.5;
  return c;
}

// The camera's pose at dt from the stamp relative to its pose at the stamp, under a constant
// velocity: a point x in the camera at dt is at R x + t in the camera at the stamp.
Eigen::Isometry3d motion(const CameraVelocity& v, double dt) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d r = v.angular * dt;
  if (r.norm() > 0) T.linear() = Eigen::AngleAxisd(r.norm(), r.normalized()).toRotationMatrix();
  T.translation() = v.linear * dt;
  return T;
}

// A wall 2 m ahead of the camera at the stamp, tilted so that depth varies across the image.
struct Wall {
  Eigen::Vector3d normal = Eigen::Vector3d(0.2, -0.1, 1).normalized();
  double offset = 2.0;  // normal . x = offset, in the camera at the stamp
  // Where the ray from origin o along d meets the wall.
  Eigen::Vector3d hit(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
    return o + d * ((offset - normal.dot(o)) / normal.dot(d));
  }
};

// The depth image a global-shutter depth camera takes dt after the stamp.
cv::Mat render_depth(const Camera& camera, const Wall& wall, const Eigen::Isometry3d& T_stamp_d) {
  cv::Mat depth(camera.height, camera.width, CV_32F);
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector3d ray = camera.back_project({u, v}, 1.0);
      const Eigen::Vector3d p = wall.hit(T_stamp_d.translation(), T_stamp_d.linear() * ray);
      depth.at<float>(v, u) = float((T_stamp_d.inverse() * p).z());
    }
  return depth;
}

// Where a rolling shutter with readout `readout` sees world point p (camera-at-stamp frame):
// the row fixes the instant, which fixes the row; iterated to a fixed point.
Eigen::Vector2d rolling_shutter_pixel(const Camera& camera, const CameraVelocity& v, double readout,
                                      const Eigen::Vector3d& p) {
  Eigen::Vector2d uv = camera.project(p);
  for (int i = 0; i < 50; ++i) {
    const double dt = readout * ((uv.y() + 0.5) / camera.height - 0.5);
    uv = camera.project(motion(v, dt).inverse() * p);
  }
  return uv;
}

struct Scene {
  Camera camera = test_camera();
  Wall wall;
  CameraVelocity velocity{Eigen::Vector3d(0.3, 1.2, -0.2), Eigen::Vector3d(0.25, -0.1, 0.15)};
  ExposureTiming timing{0.030, -0.014};
  std::vector<Eigen::Vector3d> points;  // on the wall, camera-at-stamp frame
  std::vector<cv::KeyPoint> keypoints;  // at the seen (raw = pinhole) pixels
  std::vector<Eigen::Vector2d> seen;
  std::vector<float> depths;  // as the preparation reads them: at the seen pixel
  cv::Mat depth_image;

  Scene() {
    depth_image = render_depth(camera, wall, motion(velocity, timing.depth_offset_s));
    for (int v = 40; v < 460; v += 35)
      for (int u = 40; u < 620; u += 45) {
        const Eigen::Vector3d p = wall.hit(Eigen::Vector3d::Zero(), camera.back_project({u, v}, 1));
        const Eigen::Vector2d uv = rolling_shutter_pixel(camera, velocity, timing.readout_s, p);
        const int du = int(std::lround(uv.x())), dv = int(std::lround(uv.y()));
        if (du < 0 || dv < 0 || du >= camera.width || dv >= camera.height) continue;
        points.push_back(p);
        keypoints.emplace_back(float(uv.x()), float(uv.y()), 31.0f);
        seen.push_back(uv);
        depths.push_back(depth_image.at<float>(dv, du));
      }
  }
};

TEST(ExposureUnrolling, RecoversTheGlobalShutterViewAtTheStampUnderAKnownMotion) {
  const Scene s;
  ASSERT_GT(s.points.size(), 100u);
  const UnrolledKeypoints out =
      unroll_exposure(s.keypoints, s.seen, s.depths, s.depth_image, s.camera, s.timing, s.velocity);
  double worst_seen_px = 0, worst_px = 0, worst_seen_depth = 0, worst_depth = 0;
  for (size_t i = 0; i < s.points.size(); ++i) {
    const Eigen::Vector2d truth = s.camera.project(s.points[i]);
    worst_seen_px = std::max(worst_seen_px, (s.seen[i] - truth).norm());
    worst_px = std::max(worst_px, (out.undistorted[i] - truth).norm());
    worst_seen_depth = std::max(worst_seen_depth, std::abs(s.depths[i] - s.points[i].z()));
    ASSERT_GT(out.depths[i], 0);
    worst_depth = std::max(worst_depth, std::abs(out.depths[i] - s.points[i].z()));
  }
  // As seen, the skew (1.2 rad/s x 15 ms x 525 px = 9.5 px at the top and bottom rows) and the
  // depth image's lag are far from the truth. Unrolled, what is left comes from the translation
  // being taken at the depth read at the seen pixel (another point of the wall, 14 ms later)
  // and from the depth pixel's rounding.
  EXPECT_GT(worst_seen_px, 8.0);
  EXPECT_LT(worst_px, 0.05);
  EXPECT_GT(worst_seen_depth, 0.01);
  EXPECT_LT(worst_depth, 0.002);
}

TEST(ExposureUnrolling, InstantTimingOrNoMotionLeavesTheKeypointsAsSeen) {
  const Scene s;
  const UnrolledKeypoints instant = unroll_exposure(s.keypoints, s.seen, s.depths, s.depth_image,
                                                    s.camera, ExposureTiming{}, s.velocity);
  EXPECT_EQ(instant.undistorted, s.seen);
  EXPECT_EQ(instant.depths, s.depths);
  const UnrolledKeypoints still =
      unroll_exposure(s.keypoints, s.seen, s.depths, s.depth_image, s.camera, s.timing, {});
  for (size_t i = 0; i < s.seen.size(); ++i) {
    EXPECT_LT((still.undistorted[i] - s.seen[i]).norm(), 1e-9);
    EXPECT_NEAR(still.depths[i], s.depths[i], 1e-6);
  }
}

TEST(ExposureUnrolling, AKeypointWhoseDepthPixelHoldsNoneLosesItsDepthButKeepsItsPixel) {
  Scene s;
  s.depth_image.setTo(0);
  const UnrolledKeypoints out =
      unroll_exposure(s.keypoints, s.seen, s.depths, s.depth_image, s.camera, s.timing, s.velocity);
  for (size_t i = 0; i < s.points.size(); ++i) {
    EXPECT_EQ(out.depths[i], 0.0f);
    // The pixel still moves, on the depths the preparation read.
    EXPECT_LT((out.undistorted[i] - s.camera.project(s.points[i])).norm(), 0.05);
  }
}

}  // namespace
}  // namespace slamkit
