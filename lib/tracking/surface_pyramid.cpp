#include "tracking/surface_pyramid.h"

#include <Eigen/Geometry>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "tracking/depth_pyramid.h"

namespace slamkit {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Back-projection of pixel column u / row v: x = xs[u] * z, y = ys[v] * z.
std::vector<double> ray_factors(int size, double c, double f) {
  std::vector<double> factors(size_t(size), 0);
  for (int i = 0; i < size; ++i) factors[size_t(i)] = (i - c) / f;
  return factors;
}

Surface make_surface(const cv::Mat& depth, const Camera& cam,
                     const PointToPlaneSettings& settings) {
  Surface s;
  s.camera = cam;
  s.width = depth.cols, s.height = depth.rows;
  s.pixels.resize(size_t(s.width) * size_t(s.height));
  const std::vector<double> xs = ray_factors(s.width, cam.cx, cam.fx);
  const std::vector<double> ys = ray_factors(s.height, cam.cy, cam.fy);
  // (beyond) Normals from an edge-preserving smoothed depth, as KinectFusion does.
  // The residual itself still uses the measured points.
  cv::Mat smoothed;
  if (settings.normal_smoothing_diameter > 0)
    cv::bilateralFilter(depth, smoothed, settings.normal_smoothing_diameter,
                        settings.normal_smoothing_sigma_depth,
                        settings.normal_smoothing_diameter / 2.0);
  else
    smoothed = depth;
  // The points normals are taken from: smoothed depth, where the measured depth is valid.
  std::vector<Eigen::Vector3f> source(s.pixels.size());
  const Eigen::Vector3f none = Eigen::Vector3f::Constant(kNaN);
#pragma omp parallel for schedule(static)
  for (int v = 0; v < s.height; ++v) {
    const float* measured = depth.ptr<float>(v);
    const float* smooth = smoothed.ptr<float>(v);
    const size_t row = size_t(v) * size_t(s.width);
    for (int u = 0; u < s.width; ++u) {
      SurfacePoint& sp = s.pixels[row + size_t(u)];
      sp.n = none;
      const double z = measured[u];
      if (!cam.is_valid_depth(z)) {
        sp.p = none;
        source[row + size_t(u)] = none;
        continue;
      }
      sp.p = Eigen::Vector3d(xs[size_t(u)] * z, ys[size_t(v)] * z, z).cast<float>();
      const double zs = smooth[u];
      source[row + size_t(u)] =
          Eigen::Vector3d(xs[size_t(u)] * zs, ys[size_t(v)] * zs, zs).cast<float>();
    }
  }
  // SPEC: N = (q(u+1,v) - q(u,v)) x (q(u,v+1) - q(u,v)), normalised. (beyond) Central
  // differences q(u+1,v) - q(u-1,v) etc. leave q's own noise out of its normal: with forward
  // differences the two are correlated, which on noisy smoothed depth biases each frame's
  // rotation the same way (measured by a test: 0.030 deg a frame, central 0.005 deg).
  // Neighbours across a depth edge would give the normal of a surface that is not there.
  const float max_depth_ratio = float(settings.max_neighbour_depth_ratio);
  const int back = settings.central_difference_normals ? 1 : 0;
  const size_t w = size_t(s.width);
#pragma omp parallel for schedule(static)
  for (int v = back; v < s.height - 1; ++v) {
    for (int u = back; u + 1 < s.width; ++u) {
      const size_t i = size_t(v) * w + size_t(u);
      const Eigen::Vector3f& q = source[i];
      const Eigen::Vector3f& qu0 = source[i - size_t(back)];
      const Eigen::Vector3f& qu = source[i + 1];
      const Eigen::Vector3f& qv0 = source[i - size_t(back) * w];
      const Eigen::Vector3f& qv = source[i + w];
      if (std::isnan(q.z()) || std::isnan(qu.z()) || std::isnan(qv.z()) || std::isnan(qu0.z()) ||
          std::isnan(qv0.z()))
        continue;
      const float max_step = max_depth_ratio * q.z();
      const auto too_far = [&](const Eigen::Vector3f& p) {
        return std::abs(p.z() - q.z()) > max_step;
      };
      if (too_far(qu) || too_far(qv) || too_far(qu0) || too_far(qv0)) continue;
      const Eigen::Vector3f n = (qu - qu0).cross(qv - qv0);
      if (n.squaredNorm() > 0) s.pixels[i].n = n.normalized();
    }
  }
  for (size_t i = 0; i < s.pixels.size(); ++i)
    if (s.pixels[i].has_normal()) s.with_normal.push_back(int(i));
  return s;
}

}  // namespace

SurfacePyramid make_surface_pyramid(const cv::Mat& depth, const Camera& camera,
                                    const PointToPlaneSettings& settings) {
  CV_Assert(depth.type() == CV_32F && settings.pyramid_levels >= 1);
  SurfacePyramid pyramid;
  int level = 0;
  for (const cv::Mat& image : depth_pyramid(depth, settings.pyramid_levels))
    pyramid.push_back(make_surface(image, camera_at_level(camera, level++), settings));
  return pyramid;
}

}  // namespace slamkit
