#include "tracking/photometric_equations.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace slamkit {
namespace {

// Bilinear sample at (x, y), 0 <= x < cols - 1, 0 <= y < rows - 1.
double bilinear(const cv::Mat& m, double x, double y) {
  const int x0 = int(x), y0 = int(y);
  const double ax = x - x0, ay = y - y0;
  const float *r0 = m.ptr<float>(y0), *r1 = m.ptr<float>(y0 + 1);
  return (1 - ay) * ((1 - ax) * r0[x0] + ax * r0[x0 + 1]) +
         ay * ((1 - ax) * r1[x0] + ax * r1[x0 + 1]);
}

}  // namespace

GreyPyramid make_grey_pyramid(const cv::Mat& grey, const SurfacePyramid& surfaces,
                              const PointToPlaneSettings& settings) {
  GreyPyramid pyramid(surfaces.size());
  cv::Mat level;
  grey.convertTo(level, CV_32F);
  const double min_gradient_sq =
      settings.photometric_min_gradient * settings.photometric_min_gradient;
  for (size_t l = 0; l < surfaces.size(); ++l) {
    const Surface& surface = surfaces[l];
    if (l > 0) {
      cv::Mat half;
      cv::resize(level, half, cv::Size(surface.width, surface.height), 0, 0, cv::INTER_AREA);
      level = half;
    }
    GreyLevel& out = pyramid[l];
    out.grey = level;
    cv::Sobel(level, out.gx, CV_32F, 1, 0, 3, 1.0 / 8);
    cv::Sobel(level, out.gy, CV_32F, 0, 1, 3, 1.0 / 8);
    for (int v = 1; v + 1 < surface.height; ++v) {
      const float *gx = out.gx.ptr<float>(v), *gy = out.gy.ptr<float>(v);
      for (int u = 1; u + 1 < surface.width; ++u) {
        const int i = surface.index(u, v);
        if (double(gx[u]) * gx[u] + double(gy[u]) * gy[u] >= min_gradient_sq &&
            surface.has_normal(i))
          out.edges.push_back(i);
      }
    }
  }
  return pyramid;
}

PhotometricEquations photometric_equations(const GreyLevel& prev, const GreyLevel& curr,
                                           const Surface& s, const Eigen::Isometry3d& T_prev_curr,
                                           const PointToPlaneSettings& settings) {
  const Eigen::Matrix3d R = T_prev_curr.linear();
  const Eigen::Vector3d t = T_prev_curr.translation();
  const Camera& c = s.camera;
  const double huber = settings.photometric_huber;
  PhotometricEquations eq;
  for (int i : curr.edges) {
    const int u = i % s.width, v = i / s.width;
    const double z = s.pixels(i, 0);
    const Eigen::Vector3d p =
        R * Eigen::Vector3d(s.x_factors[size_t(u)] * z, s.y_factors[size_t(v)] * z, z) + t;
    if (p.z() <= 0) continue;
    const double x = c.fx * p.x() / p.z() + c.cx, y = c.fy * p.y() / p.z() + c.cy;
    if (!(x >= 0 && y >= 0 && x < s.width - 1 && y < s.height - 1)) continue;
    const double r = bilinear(prev.grey, x, y) - curr.grey.at<float>(v, u);
    const double gx = bilinear(prev.gx, x, y), gy = bilinear(prev.gy, x, y);
    // d r / d p through the pinhole projection; the increment moves p by p x w + t (w, t the
    // 6-vector's halves), as in point-to-plane's h = (N x p, N).
    const double iz = 1 / p.z();
    const Eigen::Vector3d a(gx * c.fx * iz, gy * c.fy * iz,
                            -(gx * c.fx * p.x() + gy * c.fy * p.y()) * iz * iz);
    Eigen::Matrix<double, 6, 1> h;
    h << a.cross(p), a;
    const double w = std::abs(r) <= huber ? 1.0 : huber / std::abs(r);
    eq.H.noalias() += w * h * h.transpose();
    eq.b.noalias() += w * r * h;
    eq.sum_sq += w * r * r;
    ++eq.count;
  }
  return eq;
}

}  // namespace slamkit
