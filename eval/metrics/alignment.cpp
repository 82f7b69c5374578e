#include "eval/metrics/alignment.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/enum_names.h"
#include "core/error.h"

namespace slamkit::eval {
namespace {

// Throws when the positions are one point (to within rounding of their size): nothing then
// fixes a rotation or a scale.
void require_motion(double spread_sq, const Eigen::Vector3d& mean, size_t n,
                    const std::string& name, const std::string& what, AlignMethod method) {
  const double size = std::max(1.0, mean.norm());
  if (spread_sq > 1e-24 * size * size) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the %zu matched %s positions are all the same point (it never moves): %s "
                "alignment is undetermined; use --align translation or --align none",
                n, what.c_str(), to_string(method).c_str());
  throw_input_error(name, text);
}

}  // namespace

Eigen::Isometry3d Alignment::apply(const Eigen::Isometry3d& T_w_c) const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotation * T_w_c.rotation();
  T.translation() = apply(Eigen::Vector3d(T_w_c.translation()));
  return T;
}

Alignment align(const Trajectory& gt, const Trajectory& est, const std::vector<IndexPair>& pairs,
                AlignMethod method, size_t first_n, const std::string& gt_name,
                const std::string& est_name) {
  const size_t n = first_n == 0 ? pairs.size() : std::min(first_n, pairs.size());
  Alignment a;
  a.method = method;
  a.poses_used = method == AlignMethod::kNone ? 0 : n;
  if (method == AlignMethod::kNone || n == 0) return a;
  const auto x = [&](size_t k) -> const Eigen::Vector3d& { return est.position(pairs[k].second); };
  const auto y = [&](size_t k) -> const Eigen::Vector3d& { return gt.position(pairs[k].first); };

  if (method == AlignMethod::kTranslation) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < n; ++k) sum += y(k) - x(k);
    a.translation = sum / double(n);
    return a;
  }
  if (n == 1) {  // origin alignment: the first estimated pose onto the first groundtruth pose
    a.rotation =
        gt.pose(pairs[0].first).rotation() * est.pose(pairs[0].second).rotation().transpose();
    a.translation = y(0) - a.rotation * x(0);
    return a;
  }
  if (n == 2)
    throw_input_error(est_name,
                      "only 2 pose pairs to align on, which leave the rotation about the line "
                      "through them free; use --align-first 1 (origin), --align translation or "
                      "--align none, or give more poses");

  // Umeyama (1991), accumulated without copying the positions (a million pairs are common).
  Eigen::Vector3d mean_x = Eigen::Vector3d::Zero(), mean_y = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < n; ++k) {
    mean_x += x(k);
    mean_y += y(k);
  }
  mean_x /= double(n);
  mean_y /= double(n);
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero(), cov_x = Eigen::Matrix3d::Zero();
  double var_y = 0;
  for (size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d dx = x(k) - mean_x, dy = y(k) - mean_y;
    sigma += dy * dx.transpose();
    cov_x += dx * dx.transpose();
    var_y += dy.squaredNorm();
  }
  sigma /= double(n);
  cov_x /= double(n);
  var_y /= double(n);
  const double var_x = cov_x.trace();
  require_motion(var_x, mean_x, n, est_name, "estimated", method);
  require_motion(var_y, mean_y, n, gt_name, "groundtruth", method);

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) s(2) = -1;
  a.rotation = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
  a.scale = method == AlignMethod::kSim3 ? svd.singularValues().dot(s) / var_x : 1.0;
  a.translation = mean_y - a.scale * a.rotation * mean_x;

  double residual_sq = 0;
  for (size_t k = 0; k < n; ++k) residual_sq += (a.apply(x(k)) - y(k)).squaredNorm();
  const double residual = std::sqrt(residual_sq / double(n));
  // The long axis has the largest eigenvalue; the rms distance from it is sqrt(e0 + e1).
  const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov_x).eigenvalues();
  const double lever = a.scale * std::sqrt(std::max(0.0, e(0)) + std::max(0.0, e(1)));
  const bool on_a_line = lever <= 1e-12 * a.scale * std::sqrt(var_x);
  a.rotation_ambiguity_deg = on_a_line ? 90.0 : std::atan2(residual, lever) * 180.0 / M_PI;
  return a;
}

namespace {
constexpr EnumNames<AlignMethod, 4> kAlignNames = {{{AlignMethod::kSe3, "se3"},
                                                    {AlignMethod::kSim3, "sim3"},
                                                    {AlignMethod::kTranslation, "translation"},
                                                    {AlignMethod::kNone, "none"}}};
}  // namespace

std::string to_string(AlignMethod method) { return name_of(kAlignNames, method); }

AlignMethod parse_align_method(const std::string& text) {
  if (const auto method = value_named(kAlignNames, text)) return *method;
  throw std::invalid_argument("unknown alignment '" + text + "' (use " + choices(kAlignNames) +
                              ")");
}

}  // namespace slamkit::eval
