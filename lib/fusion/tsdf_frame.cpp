#include "fusion/tsdf_frame.h"

#include <algorithm>
#include <cmath>

#include "core/depth_noise.h"

namespace slamkit {
namespace {

// A head-on measurement at 1 m weighs 1.
const double kReferenceSigma = kinect_axial_sigma(1.0, 0.0);

}  // namespace

TsdfFrameMaker::TsdfFrameMaker(const Camera& camera, const FusionSettings& settings)
    : max_depth_(float(settings.max_depth)),
      edge_jump_(float(settings.edge_jump)),
      smoothing_radius_(settings.smoothing_radius),
      noise_weighting_(settings.noise_weighting) {
  const int s = settings.pixel_stride;
  raw_width_ = (camera.width + s - 1) / s;
  intrinsics_ = {raw_width_,           (camera.height + s - 1) / s,
                 float(camera.fx / s), float(camera.fy / s),
                 float(camera.cx / s), float(camera.cy / s)};
  for (int c = 0; c <= kIncidenceSteps; ++c)
    incidence_.push_back(float(std::acos(double(c) / kIncidenceSteps)));
  const int w = intrinsics_.width, h = intrinsics_.height;
  rays_.reserve(size_t(w * h));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      rays_.emplace_back((float(i) - intrinsics_.cx) / intrinsics_.fx,
                         (float(j) - intrinsics_.cy) / intrinsics_.fy, 1.0f);
  if (camera.distortion.is_zero()) return;
  // The depth is registered to colour in the raw lens geometry: each ideal sample takes the
  // raw sample nearest to where the lens puts its ray.
  source_.assign(rays_.size(), -1);
  for (size_t k = 0; k < rays_.size(); ++k) {
    const Eigen::Vector2d raw = camera.project_distorted(rays_[k].cast<double>()) / double(s);
    const long i = std::lround(raw.x()), j = std::lround(raw.y());
    if (i >= 0 && i < w && j >= 0 && j < h) source_[k] = int32_t(j * w + i);
  }
}

uint16_t TsdfFrameMaker::weight_of(float z, float cos_incidence) const {
  if (!noise_weighting_) return uint16_t(kTsdfWeightUnits);
  const float theta = incidence_[size_t(cos_incidence * float(kIncidenceSteps) + 0.5f)];
  const double sigma = kinect_axial_sigma(z, theta);
  const double weight = (kReferenceSigma * kReferenceSigma) / (sigma * sigma);
  return uint16_t(std::clamp(weight * kTsdfWeightUnits + 0.5, 1.0, 65535.0));
}

std::vector<float> TsdfFrameMaker::smoothed(const std::vector<float>& z) const {
  if (smoothing_radius_ == 0) return z;
  const int w = intrinsics_.width, h = intrinsics_.height, r = smoothing_radius_;
  const int window = (2 * r + 1) * (2 * r + 1);
  std::vector<float> out(z.size(), 0.0f);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const size_t k = size_t(j) * size_t(w) + size_t(i);
      const float d = z[k];
      if (d == 0) continue;
      out[k] = d;
      const float low = d - edge_jump_ * d, high = d + edge_jump_ * d;
      const bool inside = i >= r && j >= r && i + r < w && j + r < h;
      // A whole window on the surface (most samples): the plane's value at the sample is the
      // window's mean.
      if (inside) {
        float sum = 0;
        bool whole = true;
        for (int dv = -r; dv <= r && whole; ++dv)
          for (int du = -r; du <= r; ++du) {
            const float other = z[size_t(j + dv) * size_t(w) + size_t(i + du)];
            whole &= other >= low && other <= high;  // invalid samples (0) are below low
            sum += other;
          }
        if (whole) {
          out[k] = sum / float(window);
          continue;
        }
      }
      // Else the least squares plane z = a + b du + c dv over the neighbours on the surface,
      // when they are at least half the window.
      Eigen::Matrix3f normal_matrix = Eigen::Matrix3f::Zero();
      Eigen::Vector3f rhs = Eigen::Vector3f::Zero();
      int count = 0;
      for (int dv = -r; dv <= r; ++dv)
        for (int du = -r; du <= r; ++du) {
          const int ni = i + du, nj = j + dv;
          if (ni < 0 || nj < 0 || ni >= w || nj >= h) continue;
          const float other = z[size_t(nj) * size_t(w) + size_t(ni)];
          if (!(other >= low && other <= high)) continue;
          const Eigen::Vector3f row(1.0f, float(du), float(dv));
          normal_matrix += row * row.transpose();
          rhs += row * (other - d);
          ++count;
        }
      if (2 * count <= window) continue;
      const Eigen::Vector3f plane = normal_matrix.ldlt().solve(rhs);
      if (std::isfinite(plane[0])) out[k] = d + plane[0];
    }
  return out;
}

TsdfFrame TsdfFrameMaker::make(const FusionSamples& samples) const {
  const int w = intrinsics_.width, h = intrinsics_.height;
  const size_t n = size_t(w) * size_t(h);
  std::vector<float> z(n, 0.0f);
  for (size_t k = 0; k < n; ++k) {
    const int32_t from = source_.empty() ? int32_t(k) : source_[k];
    if (from < 0) continue;
    const float d = samples.depth[size_t(from)];
    if (d > 0 && d <= max_depth_) z[k] = d;
  }

  z = smoothed(z);

  TsdfFrame frame;
  frame.intrinsics = intrinsics_;
  frame.depth.assign(n, 0.0f);
  frame.weight.assign(n, 0);
  frame.rgb.assign(3 * n, 0);
  // A neighbour counts for the normal when it is on the same surface; one farther or nearer
  // than edge_jump of the depth makes the sample an edge (or a flying pixel between surfaces).
  const auto near = [&](float a, float b) { return std::abs(a - b) <= edge_jump_ * a; };
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const size_t k = size_t(j) * size_t(w) + size_t(i);
      const float d = z[k];
      if (d == 0) continue;
      const float left = i > 0 ? z[k - 1] : 0, right = i + 1 < w ? z[k + 1] : 0;
      const float up = j > 0 ? z[k - size_t(w)] : 0, down = j + 1 < h ? z[k + size_t(w)] : 0;
      bool edge = false;
      for (const float other : {left, right, up, down}) edge |= other != 0 && !near(d, other);
      if (edge) continue;
      // Tangents from the neighbours (central differences where both sides are there).
      const auto point = [&](size_t at, float depth) { return Eigen::Vector3f(rays_[at] * depth); };
      const Eigen::Vector3f here = point(k, d);
      const Eigen::Vector3f du = (right != 0 ? point(k + 1, right) : here) -
                                 (left != 0 ? point(k - 1, left) : here);
      const Eigen::Vector3f dv = (down != 0 ? point(k + size_t(w), down) : here) -
                                 (up != 0 ? point(k - size_t(w), up) : here);
      const Eigen::Vector3f normal = du.cross(dv);
      const float length = normal.norm() * rays_[k].norm();
      const float cos_incidence =
          length > 0 ? std::min(1.0f, std::abs(normal.dot(rays_[k])) / length) : 1.0f;
      frame.depth[k] = d;
      frame.weight[k] = weight_of(d, cos_incidence);
      const int32_t from = source_.empty() ? int32_t(k) : source_[k];
      const cv::Vec3b& bgr = samples.bgr[size_t(from)];
      frame.rgb[3 * k] = bgr[2];
      frame.rgb[3 * k + 1] = bgr[1];
      frame.rgb[3 * k + 2] = bgr[0];
    }
  return frame;
}

}  // namespace slamkit
