#include "tracking/surface_pyramid.h"

#include <algorithm>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "tracking/depth_pyramid.h"

namespace slamkit {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Back-projection of pixel column u / row v: x = factors[u] * z, y = factors[v] * z.
std::vector<float> ray_factors(int size, double c, double f) {
  std::vector<float> factors(size_t(size), 0);
  for (int i = 0; i < size; ++i) factors[size_t(i)] = float((i - c) / f);
  return factors;
}

// The loops below are written by hand (no library computes these normals) as plain loops
// over a row, which GCC vectorises (`omp simd`: the rows never overlap; sqrt without errno:
// lib/CMakeLists.txt): every value is computed, then `none` is added, 0 or NaN where there
// is no point or normal. Comparisons with NaN are false, so a missing depth fails the
// depth-edge test too.
Surface make_surface(const cv::Mat& depth, const Camera& cam,
                     const PointToPlaneSettings& settings) {
  Surface s;
  s.camera = cam;
  s.width = depth.cols, s.height = depth.rows;
  const int w = s.width, h = s.height;
  s.pixels.resize(long(w) * h, 4);
  float* Z = s.pixels.col(0).data();
  float* NX = s.pixels.col(1).data();
  float* NY = s.pixels.col(2).data();
  float* NZ = s.pixels.col(3).data();
  s.x_factors = ray_factors(w, cam.cx, cam.fx);
  s.y_factors = ray_factors(h, cam.cy, cam.fy);
  const float* xs = s.x_factors.data();
  const float* ys = s.y_factors.data();
  // (beyond) Normals from an edge-preserving smoothed depth, as KinectFusion does.
  // The residual itself still uses the measured points.
  cv::Mat source;  // the depth the normals are taken from; NaN where no measurement is valid
  if (settings.normal_smoothing_diameter > 0)
    cv::bilateralFilter(depth, source, settings.normal_smoothing_diameter,
                        settings.normal_smoothing_sigma_depth,
                        settings.normal_smoothing_diameter / 2.0);
  else
    source = depth.clone();
  CV_Assert(source.isContinuous());  // rows v - 1 and v + 1 are read at -w and +w
  const float min_depth = float(cam.min_depth), max_depth = float(cam.max_depth);
#pragma omp parallel for schedule(static)
  for (int v = 0; v < h; ++v) {
    const float* z = depth.ptr<float>(v);
    float* src = source.ptr<float>(v);
    float* zv = Z + size_t(v) * size_t(w);
#pragma omp simd
    for (int u = 0; u < w; ++u) {
      const float none = ((z[u] >= min_depth) & (z[u] <= max_depth)) ? 0.0f : kNaN;
      zv[u] = z[u] + none;
      src[u] += none;
    }
  }
  // The paper: N = (q(u+1,v) - q(u,v)) x (q(u,v+1) - q(u,v)), normalised. (beyond) Central
  // differences q(u+1,v) - q(u-1,v) etc. leave q's own noise out of its normal: with forward
  // differences the two are correlated, which on noisy smoothed depth biases each frame's
  // rotation the same way (measured by a test: 0.030 deg a frame, central 0.005 deg).
  // Neighbours across a depth edge would give the normal of a surface that is not there.
  // The pixels without the neighbours (the border) have no normal.
  const float max_depth_ratio = float(settings.max_neighbour_depth_ratio);
  const int back = settings.central_difference_normals ? 1 : 0;
#pragma omp parallel for schedule(static)
  for (int v = 0; v < h; ++v) {
    const size_t row = size_t(v) * size_t(w);
    float *nx = NX + row, *ny = NY + row, *nz = NZ + row;
    if (v < back || v == h - 1) {
      std::fill_n(nx, w, kNaN), std::fill_n(ny, w, kNaN), std::fill_n(nz, w, kNaN);
      continue;
    }
    nx[w - 1] = ny[w - 1] = nz[w - 1] = kNaN;  // no right neighbour
    if (back) nx[0] = ny[0] = nz[0] = kNaN;    // no left one
    const float* zc = source.ptr<float>(v);
    const float* zu = zc - back * w;  // row v - back
    const float* zd = zc + w;         // row v + 1
    const float yc = ys[v], yu = ys[v - back], yd = ys[v + 1];
#pragma omp simd
    for (int u = back; u < w - 1; ++u) {
      const float z = zc[u], zl = zc[u - back], zr = zc[u + 1];
      const float max_step = max_depth_ratio * z;
      const bool surface = (std::abs(zr - z) <= max_step) & (std::abs(zl - z) <= max_step) &
                           (std::abs(zd[u] - z) <= max_step) & (std::abs(zu[u] - z) <= max_step);
      // a = q(u+1) - q(u-back), b = q(v+1) - q(v-back), n = a x b.
      const float ax = xs[u + 1] * zr - xs[u - back] * zl, ay = yc * zr - yc * zl, az = zr - zl;
      const float bx = xs[u] * zd[u] - xs[u] * zu[u], by = yd * zd[u] - yu * zu[u];
      const float bz = zd[u] - zu[u];
      const float n_x = ay * bz - az * by, n_y = az * bx - ax * bz, n_z = ax * by - ay * bx;
      const float norm = std::sqrt(n_x * n_x + n_y * n_y + n_z * n_z);
      const float none = (surface & (norm > 0)) ? 0.0f : kNaN;
      nx[u] = n_x / norm + none;
      ny[u] = n_y / norm + none;
      nz[u] = n_z / norm + none;
    }
  }
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
