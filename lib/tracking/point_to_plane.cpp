#include "tracking/point_to_plane.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "tracking/depth_pyramid.h"

namespace slamkit {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Rows summed by one task. Fixed, so the sums do not depend on the thread count.
constexpr int kRowsPerChunk = 8;

// Camera-frame points and normals of one depth image; NaN where there are none.
struct Surface {
  int width = 0, height = 0;
  std::vector<Eigen::Vector3f> points, normals;
  int index(int u, int v) const { return v * width + u; }
};

Surface make_surface(const cv::Mat& depth, const Camera& cam,
                     const PointToPlaneSettings& settings) {
  Surface s;
  s.width = depth.cols, s.height = depth.rows;
  const Eigen::Vector3f none = Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
  s.points.assign(static_cast<size_t>(s.width) * s.height, none);
  s.normals = s.points;
#pragma omp parallel for schedule(static)
  for (int v = 0; v < s.height; ++v) {
    const float* row = depth.ptr<float>(v);
    const double y = (v - cam.cy) / cam.fy;
    for (int u = 0; u < s.width; ++u) {
      const double z = row[u];
      if (cam.is_valid_depth(z))  // Camera::back_project, without a call per pixel
        s.points[s.index(u, v)] =
            Eigen::Vector3d((u - cam.cx) / cam.fx * z, y * z, z).cast<float>();
    }
  }
  // (beyond) Normals from an edge-preserving smoothed depth, as KinectFusion does.
  // The residual itself still uses the measured points.
  std::vector<Eigen::Vector3f> smoothed_points;
  if (settings.normal_smoothing_diameter > 0) {
    cv::Mat smoothed;
    cv::bilateralFilter(depth, smoothed, settings.normal_smoothing_diameter,
                        settings.normal_smoothing_sigma_depth,
                        settings.normal_smoothing_diameter / 2.0);
    smoothed_points = s.points;
    for (int v = 0; v < s.height; ++v) {
      const float* row = smoothed.ptr<float>(v);
      for (int u = 0; u < s.width; ++u)
        if (!std::isnan(s.points[s.index(u, v)].z()))
          smoothed_points[s.index(u, v)] = Eigen::Vector3d((u - cam.cx) / cam.fx * row[u],
                                                           (v - cam.cy) / cam.fy * row[u], row[u])
                                               .cast<float>();
    }
  }
  const std::vector<Eigen::Vector3f>& normal_source =
      smoothed_points.empty() ? s.points : smoothed_points;
  // SPEC: N = (q(u+1,v) - q(u,v)) x (q(u,v+1) - q(u,v)), normalised. (beyond) Central
  // differences q(u+1,v) - q(u-1,v) etc. leave q's own noise out of its normal: with forward
  // differences the two are correlated, which on noisy smoothed depth biases each frame's
  // rotation the same way (measured by a test: 0.030 deg a frame, central 0.005 deg).
  // Neighbours across a depth edge would give the normal of a surface that is not there.
  const double max_depth_ratio = settings.max_neighbour_depth_ratio;
  const int back = settings.central_difference_normals ? 1 : 0;
#pragma omp parallel for schedule(static)
  for (int v = back; v < s.height - 1; ++v) {
    for (int u = back; u + 1 < s.width; ++u) {
      const Eigen::Vector3f& q = normal_source[s.index(u, v)];
      const Eigen::Vector3f& qu0 = normal_source[s.index(u - back, v)];
      const Eigen::Vector3f& qu = normal_source[s.index(u + 1, v)];
      const Eigen::Vector3f& qv0 = normal_source[s.index(u, v - back)];
      const Eigen::Vector3f& qv = normal_source[s.index(u, v + 1)];
      if (std::isnan(q.z()) || std::isnan(qu.z()) || std::isnan(qv.z()) || std::isnan(qu0.z()) ||
          std::isnan(qv0.z()))
        continue;
      const float max_step = static_cast<float>(max_depth_ratio) * q.z();
      const auto too_far = [&](const Eigen::Vector3f& p) {
        return std::abs(p.z() - q.z()) > max_step;
      };
      if (too_far(qu) || too_far(qv) || too_far(qu0) || too_far(qv0)) continue;
      const Eigen::Vector3f n = (qu - qu0).cross(qv - qv0);
      if (n.squaredNorm() > 0) s.normals[s.index(u, v)] = n.normalized();
    }
  }
  return s;
}

struct NormalEquations {
  Matrix6d H = Matrix6d::Zero();  // sum h h^T
  Vector6d b = Vector6d::Zero();  // sum m h
  double sum_sq = 0;              // sum m^2
  double sum_p2 = 0;              // sum |p|^2, the scale of the rotation columns
  int count = 0;
};

// Projective association of every current point with the previous surface, and the
// normal equations of the paper's linearised point-to-plane cost at T_prev_curr.
NormalEquations normal_equations(const Surface& prev, const Surface& curr, const Camera& cam,
                                 const cv::Rect& box, const Eigen::Isometry3d& T_prev_curr,
                                 const PointToPlaneSettings& settings) {
  const int chunks = (curr.height + kRowsPerChunk - 1) / kRowsPerChunk;
  std::vector<NormalEquations> partial(chunks);
  const double max_sq = settings.max_pair_distance * settings.max_pair_distance;
  const double min_cos = std::cos(settings.max_normal_angle_deg * M_PI / 180);
  const Eigen::Matrix3d R = T_prev_curr.linear();
  const Eigen::Vector3d t = T_prev_curr.translation();
#pragma omp parallel for schedule(static)
  for (int c = 0; c < chunks; ++c) {
    NormalEquations eq;  // a local, so that the compiler may keep it out of shared memory
    const int v_end = std::min(curr.height, (c + 1) * kRowsPerChunk);
    for (int v = c * kRowsPerChunk; v < v_end; ++v) {
      for (int u = 0; u < curr.width; ++u) {
        const int i = curr.index(u, v);
        if (std::isnan(curr.normals[i].z())) continue;  // a normal implies a point
        const Eigen::Vector3d p = R * curr.points[i].cast<double>() + t;
        if (p.z() <= 0) continue;
        // Nearest pixel; the box test first keeps the rounding to non-negative values.
        const double x = cam.fx * p.x() / p.z() + cam.cx + 0.5;
        const double y = cam.fy * p.y() / p.z() + cam.cy + 0.5;
        if (!(x >= box.x && x < box.x + box.width && y >= box.y && y < box.y + box.height))
          continue;
        const int pu = static_cast<int>(x), pv = static_cast<int>(y);
        const int j = prev.index(pu, pv);
        if (std::isnan(prev.normals[j].z())) continue;
        const Eigen::Vector3d q = prev.points[j].cast<double>();
        const Eigen::Vector3d n = prev.normals[j].cast<double>();
        if ((p - q).squaredNorm() > max_sq) continue;
        if ((R * curr.normals[i].cast<double>()).dot(n) < min_cos) continue;
        // h^T = N^T G with G = [[p]x | I], so h = (N x p, N).
        Vector6d h;
        h << n.cross(p), n;
        const double m = (p - q).dot(n);
        for (int r = 0; r < 6; ++r)  // upper triangle only; mirrored once at the end
          for (int c = r; c < 6; ++c) eq.H(r, c) += h(r) * h(c);
        eq.b += m * h;
        eq.sum_sq += m * m;
        eq.sum_p2 += p.squaredNorm();
        ++eq.count;
      }
    }
    partial[c] = eq;
  }
  NormalEquations total;
  for (const NormalEquations& eq : partial) {  // in chunk order: deterministic
    total.H += eq.H;
    total.b += eq.b;
    total.sum_sq += eq.sum_sq;
    total.sum_p2 += eq.sum_p2;
    total.count += eq.count;
  }
  total.H.triangularView<Eigen::StrictlyLower>() = total.H.transpose();
  return total;
}

struct Step {
  Vector6d x;             // the increment (alpha, beta, gamma, tx, ty, tz)
  double min_eigenvalue;  // conditioning, as PointToPlaneSettings::min_eigenvalue defines it
};

// The paper's own Gauss-Newton step: the 6x6 normal equations (sum h h^T) x = -sum m h
// solved by Cholesky, as SPEC prescribes (hand-written because it is the paper's method;
// every other non-linear least squares in slamkit uses Ceres). The system is first made
// comparable between scenes: per pair, with rotations measured as the displacement they
// cause at the RMS point distance, so each eigenvalue is the share of the unit
// point-to-plane information along its direction (0..1). When some direction is below
// min_eigenvalue, Cholesky would follow noise along it: the step is then taken in the
// well-constrained directions only, and that direction stays at the guess.
Step solve_step(const NormalEquations& eq, double min_eigenvalue) {
  Vector6d scale = Vector6d::Ones();
  scale.head<3>().setConstant(1 / std::sqrt(eq.sum_p2 / eq.count));
  const Matrix6d H = scale.asDiagonal() * (eq.H / eq.count) * scale.asDiagonal();
  const Vector6d b = scale.asDiagonal() * (eq.b / eq.count);
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eigen(H);
  Step step{Vector6d::Zero(), eigen.eigenvalues()(0)};
  if (step.min_eigenvalue >= min_eigenvalue) {
    step.x = H.llt().solve(-b);
  } else {
    for (int i = 0; i < 6; ++i) {
      const double lambda = eigen.eigenvalues()(i);
      if (lambda >= min_eigenvalue)
        step.x -= eigen.eigenvectors().col(i).dot(b) / lambda * eigen.eigenvectors().col(i);
    }
  }
  step.x = scale.asDiagonal() * step.x;
  return step;
}

cv::Rect box_at_level(const cv::Rect& box, int level) {
  const int scale = 1 << level;
  const int x0 = box.x / scale, y0 = box.y / scale;
  const int x1 = (box.x + box.width + scale - 1) / scale;
  const int y1 = (box.y + box.height + scale - 1) / scale;
  return {x0, y0, x1 - x0, y1 - y0};
}

// The paper's increment T_inc = [[1, g, -b, tx], [-g, 1, a, ty], [b, -a, 1, tz]] is
// I - [w]x for w = (a, b, g): a rotation by -w to first order. Applying the exact rotation
// exp(-[w]x) keeps R orthonormal without a re-orthonormalisation step.
Eigen::Isometry3d increment(const Vector6d& x) {
  Eigen::Isometry3d T_inc = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d w = x.head<3>();
  if (w.norm() > 0) T_inc.linear() = Eigen::AngleAxisd(w.norm(), -w.normalized()).matrix();
  T_inc.translation() = x.tail<3>();
  return T_inc;
}

}  // namespace

DenseAlignment point_to_plane(const cv::Mat& depth_prev, const cv::Mat& depth_curr,
                              const Camera& camera, const Eigen::Isometry3d& T_prev_curr_guess,
                              const cv::Rect& box_prev, const PointToPlaneSettings& settings) {
  CV_Assert(depth_prev.type() == CV_32F && depth_curr.type() == CV_32F);
  CV_Assert(depth_prev.size() == depth_curr.size() && settings.pyramid_levels >= 1);
  DenseAlignment result;
  result.T_prev_curr = T_prev_curr_guess;
  const std::vector<cv::Mat> prev_pyramid = depth_pyramid(depth_prev, settings.pyramid_levels);
  const std::vector<cv::Mat> curr_pyramid = depth_pyramid(depth_curr, settings.pyramid_levels);
  const cv::Rect image(0, 0, depth_prev.cols, depth_prev.rows);
  const cv::Rect box = box_prev.area() > 0 ? box_prev & image : image;

  bool converged = false;
  for (int level = settings.pyramid_levels - 1; level >= 0; --level) {
    const Camera cam = camera_at_level(camera, level);
    const Surface prev = make_surface(prev_pyramid[level], cam, settings);
    const Surface curr = make_surface(curr_pyramid[level], cam, settings);
    const cv::Rect level_box = box_at_level(box, level) & cv::Rect(0, 0, prev.width, prev.height);
    converged = false;
    for (int it = 0; it < settings.iterations_per_level && !converged; ++it) {
      const NormalEquations eq =
          normal_equations(prev, curr, cam, level_box, result.T_prev_curr, settings);
      ++result.iterations;
      result.num_correspondences = eq.count;
      if (eq.count < settings.min_correspondences) {
        result.status = DenseAlignStatus::kTooFewCorrespondences;
        return result;
      }
      result.rmse = std::sqrt(eq.sum_sq / eq.count);
      const Step step = solve_step(eq, settings.min_eigenvalue);
      result.min_eigenvalue = step.min_eigenvalue;
      result.T_prev_curr = increment(step.x) * result.T_prev_curr;
      converged = step.x.head<3>().norm() < settings.convergence_rotation &&
                  step.x.tail<3>().norm() < settings.convergence_translation;
    }
  }
  // Judged on the finest level's last iteration: earlier ones may lack pairs that the
  // guess was too far off to associate.
  result.converged = converged;
  if (result.min_eigenvalue < settings.min_eigenvalue)
    result.status = DenseAlignStatus::kIllConditioned;
  else
    result.status = converged ? DenseAlignStatus::kConverged : DenseAlignStatus::kNotConverged;
  return result;
}

}  // namespace slamkit
