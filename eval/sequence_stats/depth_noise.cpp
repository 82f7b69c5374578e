#include "eval/sequence_stats/depth_noise.h"

#include <Eigen/Dense>
#include <cmath>

#include "eval/sequence_stats/distribution.h"

namespace slamkit::stats {
namespace {

// The patch with top-left pixel (u0, v0) as 3D points, or nothing when a pixel is invalid or a
// step between neighbours is a discontinuity.
std::optional<Eigen::Matrix3Xd> patch_points(const cv::Mat& depth, const cv::Mat& rays, int u0,
                                             int v0, const DepthNoiseSettings& s) {
  const int n = s.patch;
  double sum = 0;
  for (int v = v0; v < v0 + n; ++v)
    for (int u = u0; u < u0 + n; ++u) {
      const float z = depth.at<float>(v, u);
      if (!(z > 0)) return std::nullopt;
      sum += z;
    }
  const double step = s.max_step * sum / (n * n);
  Eigen::Matrix3Xd points(3, n * n);
  for (int v = v0; v < v0 + n; ++v)
    for (int u = u0; u < u0 + n; ++u) {
      const double z = depth.at<float>(v, u);
      if ((u + 1 < u0 + n && std::abs(depth.at<float>(v, u + 1) - z) > step) ||
          (v + 1 < v0 + n && std::abs(depth.at<float>(v + 1, u) - z) > step))
        return std::nullopt;
      const cv::Vec2d& r = rays.at<cv::Vec2d>(v, u);
      points.col((v - v0) * n + (u - u0)) << r[0] * z, r[1] * z, z;
    }
  return points;
}

std::optional<PatchNoise> fit_patch(const Eigen::Matrix3Xd& points, const DepthNoiseSettings& s) {
  const Eigen::Index n = points.cols();
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const Eigen::Matrix3Xd centred = points.colwise() - centroid;
  // PCA: the normal is the direction of least spread (eigenvalues come in increasing order).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(centred * centred.transpose());
  const Eigen::Vector3d normal = pca.eigenvectors().col(0);
  if (std::abs(normal.dot(centroid.normalized())) < s.min_cos_incidence) return std::nullopt;

  // Curvature: a quadric h(a1, a2) over the plane's own axes against the plane (h = 0).
  const Eigen::VectorXd h = normal.transpose() * centred;
  const Eigen::VectorXd a1 = pca.eigenvectors().col(2).transpose() * centred;
  const Eigen::VectorXd a2 = pca.eigenvectors().col(1).transpose() * centred;
  Eigen::MatrixXd design(n, 6);
  design << Eigen::VectorXd::Ones(n), a1, a2, a1.cwiseProduct(a1), a1.cwiseProduct(a2),
      a2.cwiseProduct(a2);
  const Eigen::VectorXd quadric = design.colPivHouseholderQr().solve(h);
  const double plane_rss = h.squaredNorm();
  const double quadric_rss = (design * quadric - h).squaredNorm();
  // Below a micrometre RMS the plane is exact and the comparison would be of rounding errors.
  const bool exact = plane_rss < 1e-12 * double(n);
  if (!exact && plane_rss - quadric_rss > s.max_curvature_share * plane_rss) return std::nullopt;

  // The noise: the residual in depth of a least-squares fit of z over the ray directions, not
  // the distance to the PCA plane. The sensor errs in depth, and where that noise is not small
  // against the patch's extent (far patches) PCA tilts the plane to follow it and inflates the
  // residual (by 16% at 3 m in the tests). The quadratic terms absorb the perspective bend of a
  // tilted plane's depth; the quadric test above has already ruled out a curved surface.
  const Eigen::VectorXd x = points.row(0).cwiseQuotient(points.row(2)).transpose();
  const Eigen::VectorXd y = points.row(1).cwiseQuotient(points.row(2)).transpose();
  const Eigen::VectorXd dx = x.array() - x.mean(), dy = y.array() - y.mean();
  design << Eigen::VectorXd::Ones(n), dx, dy, dx.cwiseProduct(dx), dx.cwiseProduct(dy),
      dy.cwiseProduct(dy);
  const Eigen::VectorXd z = points.row(2).transpose();
  const Eigen::VectorXd depth_fit = design.colPivHouseholderQr().solve(z);
  const double rss = (design * depth_fit - z).squaredNorm();
  return PatchNoise{centroid.z(), std::sqrt(rss / double(n - 6))};  // the fit has 6 dof
}

}  // namespace

cv::Mat pixel_rays(const Camera& camera) {
  std::vector<Eigen::Vector2d> raw;
  raw.reserve(size_t(camera.width) * size_t(camera.height));
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) raw.emplace_back(u, v);
  const std::vector<Eigen::Vector2d> ideal =
      camera.distortion.is_zero() ? raw : camera.undistort_pixels(raw);
  cv::Mat rays(camera.height, camera.width, CV_64FC2);
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u) {
      const Eigen::Vector2d& p = ideal[size_t(v) * size_t(camera.width) + size_t(u)];
      rays.at<cv::Vec2d>(v, u) = {(p.x() - camera.cx) / camera.fx, (p.y() - camera.cy) / camera.fy};
    }
  return rays;
}

std::vector<PatchNoise> patch_noise(const cv::Mat& depth, const cv::Mat& rays,
                                    const DepthNoiseSettings& settings) {
  CV_Assert(depth.type() == CV_32FC1 && rays.type() == CV_64FC2 && depth.size() == rays.size());
  std::vector<PatchNoise> found;
  const int n = settings.patch;
  for (int v0 = 0; v0 + n <= depth.rows; v0 += n)
    for (int u0 = 0; u0 + n <= depth.cols; u0 += n)
      if (const auto points = patch_points(depth, rays, u0, v0, settings))
        if (const auto noise = fit_patch(*points, settings)) found.push_back(*noise);
  return found;
}

std::vector<DepthBin> bin_noise(const std::vector<PatchNoise>& patches,
                                const DepthNoiseSettings& settings) {
  const size_t count =
      size_t(std::round((settings.max_depth - settings.min_depth) / settings.bin_width));
  std::vector<std::vector<double>> depths(count), sigmas(count);
  for (const PatchNoise& p : patches) {
    const double k = std::floor((p.depth - settings.min_depth) / settings.bin_width);
    if (k < 0 || k >= double(count)) continue;
    depths[size_t(k)].push_back(p.depth);
    sigmas[size_t(k)].push_back(p.sigma);
  }
  std::vector<DepthBin> bins;
  for (size_t k = 0; k < count; ++k) {
    DepthBin bin;
    bin.low = settings.min_depth + double(k) * settings.bin_width;
    bin.high = bin.low + settings.bin_width;
    bin.patches = sigmas[k].size();
    bin.median_depth = median(depths[k]);
    bin.median_sigma = median(sigmas[k]);
    bins.push_back(bin);
  }
  return bins;
}

std::optional<NoiseModel> fit_noise_model(const std::vector<DepthBin>& bins,
                                          const DepthNoiseSettings& settings) {
  std::vector<const DepthBin*> used;
  for (const DepthBin& bin : bins)
    if (bin.patches >= settings.min_bin_patches) used.push_back(&bin);
  if (used.size() < 2) return std::nullopt;
  Eigen::MatrixXd design(used.size(), 2);
  Eigen::VectorXd sigma(used.size());
  for (size_t i = 0; i < used.size(); ++i) {
    const double z = used[i]->median_depth;
    design.row(Eigen::Index(i)) << 1.0, z * z;
    sigma(Eigen::Index(i)) = used[i]->median_sigma;
  }
  const Eigen::Vector2d ab = design.colPivHouseholderQr().solve(sigma);
  return NoiseModel{ab(0), ab(1), used.size()};
}

}  // namespace slamkit::stats
