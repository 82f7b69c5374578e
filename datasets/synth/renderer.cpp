#include "datasets/synth/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "datasets/synth/counter_rng.h"

namespace slamkit::synth {
namespace {

// Pixels are rendered in square tiles: the box parts one tile can see are found once.
constexpr int kTile = 16;
// Below this cosine the texture footprint stops growing: beyond it the overblur of isotropic
// mip-mapping would wash slanted floors out.
constexpr double kMinFootprintCosine = 0.25;

void punch_holes(cv::Mat& depth, const SensorModel& sensor, uint64_t seed, uint64_t frame) {
  CounterRng rng(seed, kStreamDepthHoles, frame);
  for (int i = 0; i < sensor.holes_per_frame; ++i) {
    const cv::Point centre(int(rng.uniform(0, depth.cols)), int(rng.uniform(0, depth.rows)));
    cv::circle(depth, centre, int(rng.uniform(2, 7)), cv::Scalar(0), cv::FILLED);
  }
}

class FrameRenderer {
 public:
  FrameRenderer(const SyntheticScene& scene, const Camera& camera, const Eigen::Isometry3d& T_w_c,
                const SensorModel& sensor, uint64_t seed, uint64_t frame_index)
      : scene_(scene),
        camera_(camera),
        R_w_c_(T_w_c.linear()),
        origin_(T_w_c.translation()),
        sensor_(sensor),
        min_cos_incidence_(sensor.min_cos_incidence()),
        seed_(seed),
        first_pixel_(frame_index * uint64_t(camera.width) * uint64_t(camera.height)) {}

  // World direction of the ray through pixel (u, v), scaled to camera z = 1 so that the ray
  // parameter of a hit is its depth.
  Eigen::Vector3d ray(int u, int v) const {
    return R_w_c_ *
           Eigen::Vector3d((u - camera_.cx) / camera_.fx, (v - camera_.cy) / camera_.fy, 1);
  }

  void render_tile(int u0, int v0, int u1, int v1, RenderedFrame& out) const {
    const std::vector<int> parts =
        scene_.parts_in_cone(origin_, {ray(u0, v0), ray(u1, v0), ray(u1, v1), ray(u0, v1)});
    for (int v = v0; v <= v1; ++v) {
      auto* bgr = out.bgr.ptr<cv::Vec3b>(v);
      auto* depth = out.depth.ptr<uint16_t>(v);
      for (int u = u0; u <= u1; ++u) render_pixel(u, v, parts, bgr[u], depth[u]);
    }
  }

 private:
  void render_pixel(int u, int v, const std::vector<int>& parts, cv::Vec3b& bgr,
                    uint16_t& depth) const {
    const Eigen::Vector3d d_w = ray(u, v);
    CounterRng rng(seed_, kStreamPixel, first_pixel_ + uint64_t(v) * camera_.width + u);
    const auto hit = scene_.cast_ray(origin_, d_w, parts);
    if (!hit) {  // only if the camera left the room
      bgr = cv::Vec3b(0, 0, 0);
      depth = 0;
      return;
    }
    const double length = d_w.norm();
    const double cos_incidence = std::abs(hit->normal.dot(d_w)) / length;
    const double footprint =
        hit->t * length / camera_.fx / std::max(cos_incidence, kMinFootprintCosine);
    const Eigen::Vector3f colour = scene_.colour(*hit, footprint);
    for (int c = 0; c < 3; ++c)
      bgr[c] = cv::saturate_cast<uint8_t>(colour[c] + sensor_.colour_sigma * rng.approx_gaussian());
    depth =
        sensor_.measure_depth(hit->t, cos_incidence < min_cos_incidence_, camera_.depth_scale, rng);
  }

  const SyntheticScene& scene_;
  const Camera& camera_;
  const Eigen::Matrix3d R_w_c_;
  const Eigen::Vector3d origin_;
  const SensorModel& sensor_;
  const double min_cos_incidence_;
  const uint64_t seed_;
  const uint64_t first_pixel_;  // pixel counter of the frame's first pixel
};

}  // namespace

RenderedFrame render_frame(const SyntheticScene& scene, const Camera& camera,
                           const Eigen::Isometry3d& T_w_c, const SensorModel& sensor, uint64_t seed,
                           uint64_t frame_index) {
  RenderedFrame out{cv::Mat(camera.height, camera.width, CV_8UC3),
                    cv::Mat(camera.height, camera.width, CV_16UC1)};
  const FrameRenderer renderer(scene, camera, T_w_c, sensor, seed, frame_index);
  for (int v0 = 0; v0 < camera.height; v0 += kTile)
    for (int u0 = 0; u0 < camera.width; u0 += kTile)
      renderer.render_tile(u0, v0, std::min(u0 + kTile, camera.width) - 1,
                           std::min(v0 + kTile, camera.height) - 1, out);
  punch_holes(out.depth, sensor, seed, frame_index);
  return out;
}

}  // namespace slamkit::synth
