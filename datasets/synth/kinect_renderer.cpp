#include "datasets/synth/kinect_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "datasets/synth/counter_rng.h"

namespace slamkit::synth {
namespace {

// As the ideal renderer (renderer.cpp): square tiles share one culling of the box parts, and a
// row band of tiles shares one pose (the rolling shutter's granularity).
constexpr int kTile = 16;
constexpr double kMinFootprintCosine = 0.25;
// Depth rays are jittered by lateral noise, at most 4.9 sigma of its largest sigma (1.1 px,
// KinectSettings::lateral_sigma_px at 80 deg): tiles' culling cones are widened by this.
constexpr double kConeMarginPx = 6.0;

// Cone edges (world) round the rays of pixels u0..u1 x v0..v1, `margin` pixels wider.
std::array<Eigen::Vector3d, 4> tile_cone(const std::vector<Eigen::Vector3d>& rays, int width,
                                         int u0, int v0, int u1, int v1, double margin_x,
                                         double margin_y, const Eigen::Matrix3d& R_w_c) {
  Eigen::Vector2d lo(1e9, 1e9), hi(-1e9, -1e9);
  for (int v = v0; v <= v1; ++v)
    for (int u = u0; u <= u1; ++u) {
      const Eigen::Vector2d p = rays[size_t(v) * width + u].head<2>();
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
  lo -= Eigen::Vector2d(margin_x, margin_y), hi += Eigen::Vector2d(margin_x, margin_y);
  return {R_w_c * Eigen::Vector3d(lo.x(), lo.y(), 1), R_w_c * Eigen::Vector3d(hi.x(), lo.y(), 1),
          R_w_c * Eigen::Vector3d(hi.x(), hi.y(), 1), R_w_c * Eigen::Vector3d(lo.x(), hi.y(), 1)};
}

// Lit colour along a ray (camera-frame direction at z = 1), prefiltered for a pixel's footprint.
Eigen::Vector3f radiance(const SyntheticScene& scene, const Camera& camera,
                         const Eigen::Isometry3d& T_w_c, const Eigen::Vector3d& ray_c,
                         const std::vector<int>& parts) {
  const Eigen::Vector3d d_w = T_w_c.linear() * ray_c;
  const auto hit = scene.cast_ray(T_w_c.translation(), d_w, parts);
  if (!hit) return Eigen::Vector3f::Zero();  // only if the camera left the room
  const double length = d_w.norm();
  const double cos_incidence = std::abs(hit->normal.dot(d_w)) / length;
  const double footprint =
      hit->t * length / camera.fx / std::max(cos_incidence, kMinFootprintCosine);
  return scene.colour(*hit, footprint);
}

std::vector<Eigen::Vector3d> pinhole_rays(const Camera& camera) {
  std::vector<Eigen::Vector3d> rays;
  rays.reserve(size_t(camera.width) * camera.height);
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u)
      rays.emplace_back((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1);
  return rays;
}

// 1 at the centre, 1 - vignetting at the corners, quadratic in the radius between.
double vignette(const Camera& camera, const KinectSettings& s, int u, int v) {
  if (!s.has(KinectEffect::kVignetting)) return 1;
  const double dx = u - camera.cx, dy = v - camera.cy;
  const double corner2 = camera.cx * camera.cx + camera.cy * camera.cy;
  return 1 - s.vignetting * (dx * dx + dy * dy) / corner2;
}

struct DepthSample {
  double z = 0;      // camera z of the surface, 0 when nothing is measured
  double theta = 0;  // incidence angle, radians
};

// The first pass over the depth image: what the IR camera sees along each (laterally
// jittered) ray, and whether the projector lights it.
DepthSample sample_depth(const SyntheticScene& scene, const Camera& camera,
                         const Eigen::Isometry3d& T_w_d, const KinectSettings& s,
                         const std::vector<int>& parts, int u, int v, CounterRng& rng) {
  double x = u, y = v;
  if (s.has(KinectEffect::kDepthNoise)) {
    // Where the surface at the pixel centre is seen, its incidence sets the lateral noise.
    const Eigen::Vector3d d0 = T_w_d.linear() * Eigen::Vector3d((u - camera.cx) / camera.fx,
                                                                (v - camera.cy) / camera.fy, 1);
    const auto hit0 = scene.cast_ray(T_w_d.translation(), d0, parts);
    if (hit0) {
      const double theta = std::acos(std::min(1.0, std::abs(hit0->normal.dot(d0)) / d0.norm()));
      const double sigma = KinectSettings::lateral_sigma_px(theta);
      x += sigma * rng.approx_gaussian8(), y += sigma * rng.approx_gaussian8();
    }
  }
  const Eigen::Vector3d d_w =
      T_w_d.linear() * Eigen::Vector3d((x - camera.cx) / camera.fx, (y - camera.cy) / camera.fy, 1);
  const auto hit = scene.cast_ray(T_w_d.translation(), d_w, parts);
  if (!hit) return {};
  const double cos_incidence = std::abs(hit->normal.dot(d_w)) / d_w.norm();
  DepthSample sample{hit->t, std::acos(std::min(1.0, cos_incidence))};
  if (s.has(KinectEffect::kProjectorShadow)) {
    // The projector sits baseline_m along the IR camera's x: a surface it cannot see through
    // the scene carries no pattern and gets no depth. The whole scene is tested, not the
    // tile's parts: the projector looks from elsewhere.
    const Eigen::Vector3d projector = T_w_d * Eigen::Vector3d(s.baseline_m, 0, 0);
    const Eigen::Vector3d to_point = hit->point - projector;
    const auto blocker = scene.cast_ray(projector, to_point);
    if (blocker && blocker->t < 1 - 1e-3 / to_point.norm()) return {};  // 1 mm short of it
  }
  return sample;
}

}  // namespace

std::vector<Eigen::Vector3d> colour_pixel_rays(const Camera& camera, const KinectSettings& s) {
  std::vector<Eigen::Vector3d> rays = pinhole_rays(camera);
  if (!s.has(KinectEffect::kLensDistortion)) return rays;
  const Camera distorted = kinect_colour_camera(camera, s);
  std::vector<Eigen::Vector2d> raw;
  raw.reserve(rays.size());
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) raw.emplace_back(u, v);
  const std::vector<Eigen::Vector2d> ideal = distorted.undistort_pixels(raw);
  for (size_t i = 0; i < rays.size(); ++i)
    rays[i] = Eigen::Vector3d((ideal[i].x() - camera.cx) / camera.fx,
                              (ideal[i].y() - camera.cy) / camera.fy, 1);
  return rays;
}

Camera kinect_colour_camera(const Camera& camera, const KinectSettings& s) {
  Camera c = camera;
  if (s.has(KinectEffect::kLensDistortion)) c.distortion = {s.k1, s.k2, s.p1, s.p2, s.k3};
  if (s.has(KinectEffect::kRollingShutter)) c.readout_time = s.readout_s;
  c.exact_depth_stamps = s.has(KinectEffect::kStreamTiming);  // the stamps are the render's
  return c;
}

int exposure_subframes(const SyntheticScene& scene, const Camera& camera, const PoseAt& pose_at,
                       const KinectSettings& s, double t) {
  if (!s.has(KinectEffect::kMotionBlur)) return 1;
  const Eigen::Isometry3d start = pose_at(t - s.exposure_s / 2);
  const Eigen::Isometry3d end = pose_at(t + s.exposure_s / 2);
  double moved_px = 0;
  for (double fu : {0.0, 0.5, 1.0})
    for (double fv : {0.0, 0.5, 1.0}) {
      const Eigen::Vector2d uv(fu * (camera.width - 1), fv * (camera.height - 1));
      const Eigen::Vector3d ray = start.linear() * camera.back_project(uv, 1.0);
      const auto hit = scene.cast_ray(start.translation(), ray);
      if (!hit) continue;
      const Eigen::Vector3d p_end = end.inverse() * hit->point;
      if (p_end.z() <= 0) return s.max_subframes;  // swung right round: as blurred as it gets
      moved_px = std::max(moved_px, (camera.project(p_end) - uv).norm());
    }
  return std::clamp(int(std::ceil(moved_px / s.blur_step_px)), 1, s.max_subframes);
}

double exposure_gain(const KinectSettings& s, uint64_t seed, double t) {
  if (!s.has(KinectEffect::kAutoExposure)) return 1;
  // Two slow waves (11 s and 4.3 s periods) with seeded phases: smooth, and the same for any
  // frame order. The gain starts at its mean.
  CounterRng rng(seed, kStreamExposure, 0);
  const double phase1 = rng.uniform(0, 2 * M_PI), phase2 = rng.uniform(0, 2 * M_PI);
  const double wander = 0.7 * (std::sin(2 * M_PI * t / 11.0 + phase1) - std::sin(phase1)) +
                        0.3 * (std::sin(2 * M_PI * t / 4.3 + phase2) - std::sin(phase2));
  return std::exp(s.exposure_drift * wander);
}

cv::Mat render_kinect_colour(const SyntheticScene& scene, const Camera& camera,
                             const std::vector<Eigen::Vector3d>& rays, const PoseAt& pose_at,
                             const KinectSettings& s, uint64_t seed, uint64_t frame_index,
                             double t) {
  const int width = camera.width, height = camera.height;
  const int subframes = exposure_subframes(scene, camera, pose_at, s, t);
  const double gain = exposure_gain(s, seed, t);
  const double readout = s.has(KinectEffect::kRollingShutter) ? s.readout_s : 0.0;
  cv::Mat sum(height, width, CV_32FC3, cv::Scalar::all(0));
  for (int v0 = 0; v0 < height; v0 += kTile) {
    const int v1 = std::min(v0 + kTile, height) - 1;
    const double band_time = t + readout * ((v0 + v1 + 1) / 2.0 / height - 0.5);
    for (int k = 0; k < subframes; ++k) {
      const double sub_time =
          subframes == 1 ? band_time : band_time + s.exposure_s * ((k + 0.5) / subframes - 0.5);
      const Eigen::Isometry3d T_w_c = pose_at(sub_time);
      for (int u0 = 0; u0 < width; u0 += kTile) {
        const int u1 = std::min(u0 + kTile, width) - 1;
        const std::vector<int> parts = scene.parts_in_cone(
            T_w_c.translation(), tile_cone(rays, width, u0, v0, u1, v1, 0, 0, T_w_c.linear()));
        for (int v = v0; v <= v1; ++v) {
          auto* row = sum.ptr<cv::Vec3f>(v);
          for (int u = u0; u <= u1; ++u) {
            const Eigen::Vector3f c =
                radiance(scene, camera, T_w_c, rays[size_t(v) * width + u], parts);
            for (int ch = 0; ch < 3; ++ch) row[u][ch] += c[ch];
          }
        }
      }
    }
  }
  // The sensor: exposure gain and vignetting scale the light, shot noise (variance growing with
  // the signal) and read noise are added, and the result is quantised to 8 bits.
  cv::Mat bgr(height, width, CV_8UC3);
  const bool noisy = s.has(KinectEffect::kColourNoise);
  const uint64_t first_pixel = frame_index * uint64_t(width) * uint64_t(height);
  for (int v = 0; v < height; ++v) {
    const auto* in = sum.ptr<cv::Vec3f>(v);
    auto* out = bgr.ptr<cv::Vec3b>(v);
    for (int u = 0; u < width; ++u) {
      const double scale = gain * vignette(camera, s, u, v) / subframes;
      CounterRng rng(seed, kStreamColourNoise, first_pixel + uint64_t(v) * width + u);
      for (int ch = 0; ch < 3; ++ch) {
        double level = in[u][ch] * scale;
        if (noisy)
          level += std::sqrt(s.read_noise * s.read_noise + s.shot_gain * std::max(level, 0.0)) *
                   rng.approx_gaussian();
        out[u][ch] = cv::saturate_cast<uint8_t>(level);
      }
    }
  }
  return bgr;
}

Eigen::Isometry3d depth_camera_pose(const Eigen::Isometry3d& T_w_colour, const KinectSettings& s) {
  if (!s.has(KinectEffect::kMisregistration)) return T_w_colour;
  Eigen::Isometry3d T_c_d = Eigen::Isometry3d::Identity();
  T_c_d.linear() =
      Eigen::AngleAxisd(s.misregistration_deg * M_PI / 180, Eigen::Vector3d::UnitY()).matrix();
  T_c_d.translation() = Eigen::Vector3d(s.misregistration_m, 0, 0);
  return T_w_colour * T_c_d;
}

cv::Mat render_kinect_depth(const SyntheticScene& scene, const Camera& camera,
                            const Eigen::Isometry3d& T_w_d, const KinectSettings& s, uint64_t seed,
                            uint64_t depth_index) {
  const int width = camera.width, height = camera.height;
  const std::vector<Eigen::Vector3d> rays = pinhole_rays(camera);
  const uint64_t first_pixel = depth_index * uint64_t(width) * uint64_t(height);
  const auto pixel_id = [&](int u, int v) { return first_pixel + uint64_t(v) * width + u; };
  const double margin = s.has(KinectEffect::kDepthNoise) ? kConeMarginPx : 0.0;

  std::vector<DepthSample> samples(size_t(width) * height);
  for (int v0 = 0; v0 < height; v0 += kTile)
    for (int u0 = 0; u0 < width; u0 += kTile) {
      const int u1 = std::min(u0 + kTile, width) - 1, v1 = std::min(v0 + kTile, height) - 1;
      const std::vector<int> parts = scene.parts_in_cone(
          T_w_d.translation(), tile_cone(rays, width, u0, v0, u1, v1, margin / camera.fx,
                                         margin / camera.fy, T_w_d.linear()));
      for (int v = v0; v <= v1; ++v)
        for (int u = u0; u <= u1; ++u) {
          CounterRng rng(seed, kStreamDepthLateral, pixel_id(u, v));
          samples[size_t(v) * width + u] = sample_depth(scene, camera, T_w_d, s, parts, u, v, rng);
        }
    }

  const double max_theta = s.max_incidence_deg * M_PI / 180;
  cv::Mat depth(height, width, CV_16UC1, cv::Scalar(0));
  for (int v = 0; v < height; ++v) {
    auto* out = depth.ptr<uint16_t>(v);
    for (int u = 0; u < width; ++u) {
      const DepthSample& sample = samples[size_t(v) * width + u];
      double z = sample.z;
      if (z <= 0) continue;
      if (s.has(KinectEffect::kDepthEdges)) {
        // The correlation window straddles a depth edge: the pixel on the near side often
        // returns nothing or a depth between the two surfaces (a flying pixel).
        double far = z;
        for (const auto& [du, dv] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
          const int nu = u + du, nv = v + dv;
          if (nu < 0 || nv < 0 || nu >= width || nv >= height) continue;
          far = std::max(far, samples[size_t(nv) * width + nu].z);
        }
        if (far > z * (1 + s.edge_jump)) {
          CounterRng rng(seed, kStreamDepthEdges, pixel_id(u, v));
          const double draw = rng.uniform();
          if (draw < s.edge_missing) continue;
          if (draw < s.edge_missing + s.edge_flying) z += rng.uniform(0.1, 0.9) * (far - z);
        }
      }
      if (z < s.min_range_m || z > s.max_range_m || sample.theta > max_theta) continue;
      CounterRng rng(seed, kStreamDepthNoise, pixel_id(u, v));
      if (rng.uniform() < s.dropout_probability) continue;
      if (s.has(KinectEffect::kDepthNoise)) {
        // Nguyen et al.'s sigma is the whole error of a real Kinect, quantisation included: when
        // quantisation is simulated too, the noise drawn before it is the rest.
        const double sigma = KinectSettings::axial_sigma(z, sample.theta);
        const double step = s.has(KinectEffect::kDepthQuantisation) ? s.depth_step(z) : 0.0;
        z += std::sqrt(std::max(sigma * sigma - step * step / 12, 0.25 * sigma * sigma)) *
             rng.approx_gaussian8();
      }
      if (s.has(KinectEffect::kDepthQuantisation)) z = s.quantise_depth(z);
      const long raw = std::lround(z * camera.depth_scale);
      out[u] = raw < 1 || raw > 65535 ? 0 : uint16_t(raw);
    }
  }
  CounterRng holes(seed, kStreamDepthHoles, depth_index);
  for (int i = 0; i < s.holes_per_frame; ++i) {
    const cv::Point centre(int(holes.uniform(0, width)), int(holes.uniform(0, height)));
    cv::circle(depth, centre, int(holes.uniform(2, 7)), cv::Scalar(0), cv::FILLED);
  }
  return depth;
}

}  // namespace slamkit::synth
