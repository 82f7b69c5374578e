#include "tracking/icp_svd_ransac.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <random>

namespace slamkit {
namespace {

constexpr int kMinimalSample = 3;
constexpr int kMaxRefits = 3;  // refit on the inliers until the set stops changing

// 2 * area / longest_edge^2 of a triangle: 0 when collinear, 0.87 when equilateral.
double triangle_shape(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const Eigen::Vector3d& c) {
  const double longest =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return longest > 0 ? (b - a).cross(c - a).norm() / longest : 0;
}

// A sample is used only when its triangles are well shaped in both frames and their edge
// lengths agree: a rigid motion keeps distances, so a mismatch means an outlier is in it
// (this check is cheaper than the fit it saves).
bool usable_sample(const std::vector<Eigen::Vector3d>& q_prev,
                   const std::vector<Eigen::Vector3d>& q_curr, const std::vector<double>& thr,
                   const int (&s)[kMinimalSample], const RansacSettings& settings) {
  for (int a = 0; a < kMinimalSample; ++a) {
    const int i = s[a], j = s[(a + 1) % kMinimalSample];
    const double d_prev = (q_prev[i] - q_prev[j]).norm();
    const double d_curr = (q_curr[i] - q_curr[j]).norm();
    if (d_prev < settings.min_sample_spread || d_curr < settings.min_sample_spread) return false;
    if (std::abs(d_prev - d_curr) > thr[i] + thr[j]) return false;
  }
  return triangle_shape(q_prev[s[0]], q_prev[s[1]], q_prev[s[2]]) >= settings.min_sample_shape &&
         triangle_shape(q_curr[s[0]], q_curr[s[1]], q_curr[s[2]]) >= settings.min_sample_shape;
}

int count_inliers(const std::vector<Eigen::Vector3d>& q_prev,
                  const std::vector<Eigen::Vector3d>& q_curr, const std::vector<double>& thr,
                  const Eigen::Isometry3d& T, std::vector<bool>* inliers) {
  int count = 0;
  for (size_t i = 0; i < q_prev.size(); ++i) {
    const bool in = (q_prev[i] - T * q_curr[i]).squaredNorm() < thr[i] * thr[i];
    if (inliers) (*inliers)[i] = in;
    count += in;
  }
  return count;
}

// Samples needed so that one is all-inlier with the given confidence (Fischler-Bolles).
int adaptive_iterations(double inlier_ratio, const RansacSettings& settings) {
  const double all_inlier = std::pow(inlier_ratio, kMinimalSample);
  if (all_inlier >= 1) return 1;
  const double n = std::log(1 - settings.confidence) / std::log1p(-all_inlier);
  return n < settings.max_iterations ? static_cast<int>(std::ceil(n)) : settings.max_iterations;
}

}  // namespace

std::optional<Eigen::Isometry3d> fit_rigid(const std::vector<Eigen::Vector3d>& q_prev,
                                           const std::vector<Eigen::Vector3d>& q_curr,
                                           const std::vector<int>& indices) {
  const int n = static_cast<int>(indices.size());
  if (n < kMinimalSample) return std::nullopt;
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (int k = 0; k < n; ++k) {
    src.col(k) = q_curr[indices[k]];
    dst.col(k) = q_prev[indices[k]];
  }
  // Collinear (or coincident) points leave the rotation about their line free.
  const Eigen::Matrix3Xd centred = src.colwise() - src.rowwise().mean();
  const Eigen::Vector3d spread =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(centred * centred.transpose(),
                                                     Eigen::EigenvaluesOnly)
          .eigenvalues();  // ascending
  if (!(spread(1) > 1e-6 * spread(2)) || spread(2) <= 0) return std::nullopt;
  // Umeyama without scale is exactly the paper's closed form: W = U S V^T, R = U V^T with the
  // reflection fix, t = p_c - R p'_c.
  Eigen::Isometry3d T;
  T.matrix() = Eigen::umeyama(src, dst, false);
  return T;
}

double ransac_threshold(const RansacSettings& settings, double z) {
  return settings.threshold_base + settings.threshold_quadratic * z * z;
}

RigidFit icp_svd_ransac(const std::vector<Eigen::Vector3d>& q_prev,
                        const std::vector<Eigen::Vector3d>& q_curr,
                        const RansacSettings& settings) {
  RigidFit fit;
  const int n = static_cast<int>(q_prev.size());
  if (n < kMinimalSample || q_curr.size() != q_prev.size()) return fit;
  fit.status = RigidFitStatus::kDegenerate;

  std::vector<double> thr(n);
  for (int i = 0; i < n; ++i) thr[i] = ransac_threshold(settings, q_prev[i].z());

  std::mt19937 rng(settings.seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  int best_count = 0;
  Eigen::Isometry3d best = Eigen::Isometry3d::Identity();
  int needed = settings.max_iterations;
  // Degenerate samples count as iterations too, so the loop always ends.
  for (; fit.iterations < needed; ++fit.iterations) {
    int s[kMinimalSample];
    for (int k = 0; k < kMinimalSample;) {
      s[k] = pick(rng);
      if (std::find(s, s + k, s[k]) == s + k) ++k;  // distinct indices
    }
    if (!usable_sample(q_prev, q_curr, thr, s, settings)) continue;
    const auto T = fit_rigid(q_prev, q_curr, {s[0], s[1], s[2]});
    if (!T) continue;
    const int count = count_inliers(q_prev, q_curr, thr, *T, nullptr);
    if (count > best_count) {
      best_count = count;
      best = *T;
      needed = adaptive_iterations(static_cast<double>(count) / n, settings);
    }
  }
  if (best_count < kMinimalSample) return fit;

  std::vector<bool> inliers(n);
  count_inliers(q_prev, q_curr, thr, best, &inliers);
  for (int refit = 0; refit < kMaxRefits; ++refit) {
    std::vector<int> indices;
    for (int i = 0; i < n; ++i)
      if (inliers[i]) indices.push_back(i);
    const auto T = fit_rigid(q_prev, q_curr, indices);
    if (!T) return fit;
    best = *T;
    std::vector<bool> updated(n);
    count_inliers(q_prev, q_curr, thr, best, &updated);
    const bool stable = updated == inliers;
    inliers = std::move(updated);
    if (stable) break;
  }

  fit.T_prev_curr = best;
  double sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    if (!inliers[i]) continue;
    ++fit.num_inliers;
    sum_sq += (q_prev[i] - best * q_curr[i]).squaredNorm();
  }
  if (fit.num_inliers < kMinimalSample) return fit;
  fit.inlier_rmse = std::sqrt(sum_sq / fit.num_inliers);
  fit.inliers = std::move(inliers);
  fit.status = RigidFitStatus::kOk;
  return fit;
}

}  // namespace slamkit
