#include "tracking/point_to_plane.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "tracking/point_to_plane_equations.h"

namespace slamkit {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct Step {
  Vector6d x;             // the increment (alpha, beta, gamma, tx, ty, tz)
  double min_eigenvalue;  // conditioning, as PointToPlaneSettings::min_eigenvalue defines it
};

// The paper's own Gauss-Newton step: the 6x6 normal equations (sum h h^T) x = -sum m h
// solved by Cholesky, as the paper does (hand-written because it is the paper's method;
// every other non-linear least squares in slamkit uses Ceres). The system is first made
// comparable between scenes: per pair, with rotations measured as the displacement they
// cause at the RMS point distance, so each eigenvalue is the share of the unit
// point-to-plane information along its direction (0..1; the photometric term's information,
// when added, counts in the same unit). When some direction is below
// min_eigenvalue, Cholesky would follow noise along it: the step is then taken in the
// well-constrained directions only, and that direction stays at the guess.
Step solve_step(const PointToPlaneEquations& eq, double min_eigenvalue) {
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

DenseAlignment point_to_plane(const SurfacePyramid& prev, const SurfacePyramid& curr,
                              const Eigen::Isometry3d& T_prev_curr_guess, const cv::Rect& box_prev,
                              const PointToPlaneSettings& settings, const GreyPyramid* prev_grey,
                              const GreyPyramid* curr_grey) {
  const bool photometric = prev_grey && curr_grey && settings.photometric_weight > 0;
  CV_Assert(!prev.empty() && prev.size() == curr.size());
  CV_Assert(prev[0].width == curr[0].width && prev[0].height == curr[0].height);
  DenseAlignment result;
  result.T_prev_curr = T_prev_curr_guess;
  const cv::Rect image(0, 0, prev[0].width, prev[0].height);
  const cv::Rect box = box_prev.area() > 0 ? box_prev & image : image;

  bool converged = false;
  for (int level = int(prev.size()) - 1; level >= 0; --level) {
    const Surface& prev_level = prev[size_t(level)];
    const Surface& curr_level = curr[size_t(level)];
    const cv::Rect level_box =
        box_at_level(box, level) & cv::Rect(0, 0, prev_level.width, prev_level.height);
    converged = false;
    for (int it = 0; it < settings.iterations_per_level && !converged; ++it) {
      PointToPlaneEquations eq =
          point_to_plane_equations(prev_level, curr_level, level_box, result.T_prev_curr, settings);
      ++result.iterations;
      result.num_correspondences = eq.count;
      if (eq.count < settings.min_correspondences) {
        result.status = DenseAlignStatus::kTooFewCorrespondences;
        return result;
      }
      result.rmse = std::sqrt(eq.sum_sq / eq.count);
      if (photometric) {
        const PhotometricEquations photo =
            photometric_equations((*prev_grey)[size_t(level)], (*curr_grey)[size_t(level)],
                                  curr_level, result.T_prev_curr, settings);
        eq.H += settings.photometric_weight * photo.H;
        eq.b += settings.photometric_weight * photo.b;
      }
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
