#include "tracking/point_to_plane_equations.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slamkit {
namespace {

// Current points per block. Fixed, so that each block's sums, and the order in which they
// are added, do not depend on the thread count.
constexpr size_t kPointsPerBlock = 4096;

// One column per pair: (h, m). Its Gram matrix holds sum h h^T, sum m h and sum m^2.
using Rows = Eigen::Matrix<float, 7, Eigen::Dynamic>;
using Moments = Eigen::Matrix<double, 7, 7>;

}  // namespace

PointToPlaneEquations point_to_plane_equations(const Surface& prev, const Surface& curr,
                                               const cv::Rect& box,
                                               const Eigen::Isometry3d& T_prev_curr,
                                               const PointToPlaneSettings& settings) {
  const std::vector<int>& points = curr.with_normal;
  const size_t blocks = (points.size() + kPointsPerBlock - 1) / kPointsPerBlock;
  std::vector<Moments> moments(blocks);
  std::vector<double> sum_p2(blocks);
  std::vector<int> counts(blocks);
  // Single precision per pair (twice the SIMD width, and the depth noise is ~1e4 times the
  // rounding); each block's sums go to double before they are added up.
  const Eigen::Matrix3f R = T_prev_curr.linear().cast<float>();
  const Eigen::Vector3f t = T_prev_curr.translation().cast<float>();
  const Camera& cam = prev.camera;
  const float fx = float(cam.fx), fy = float(cam.fy);
  // +0.5: the nearest pixel by truncation, kept non-negative by the box test before it.
  const float cx = float(cam.cx + 0.5), cy = float(cam.cy + 0.5);
  const float x0 = float(box.x), x1 = float(box.x + box.width);
  const float y0 = float(box.y), y1 = float(box.y + box.height);
  const float max_sq = float(settings.max_pair_distance * settings.max_pair_distance);
  const float min_cos = float(std::cos(settings.max_normal_angle_deg * M_PI / 180));
#pragma omp parallel
  {
    Rows rows(7, long(kPointsPerBlock));  // this thread's buffer
#pragma omp for schedule(static)
    for (size_t c = 0; c < blocks; ++c) {
      long n = 0;
      double p2 = 0;
      const size_t end = std::min(points.size(), (c + 1) * kPointsPerBlock);
      for (size_t k = c * kPointsPerBlock; k < end; ++k) {
        const SurfacePoint& current = curr.pixels[size_t(points[k])];
        const Eigen::Vector3f p = R * current.p + t;
        if (p.z() <= 0) continue;
        const float x = fx * p.x() / p.z() + cx, y = fy * p.y() / p.z() + cy;
        if (!(x >= x0 && x < x1 && y >= y0 && y < y1)) continue;
        const SurfacePoint& previous = prev.at(int(x), int(y));
        if (!previous.has_normal()) continue;
        const Eigen::Vector3f d = p - previous.p;
        if (d.squaredNorm() > max_sq) continue;
        if ((R * current.n).dot(previous.n) < min_cos) continue;
        // Fixed-size writes: a comma initialiser into the dynamic column copies the
        // 3-vectors with 4-float loads (GCC: -Warray-bounds).
        rows.col(n).head<3>() = previous.n.cross(p);
        rows.col(n).segment<3>(3) = previous.n;
        rows(6, n++) = d.dot(previous.n);
        p2 += double(p.squaredNorm());
      }
      // The Gram matrix by Eigen's symmetric rank update (vectorised), lower triangle.
      Eigen::Matrix<float, 7, 7> gram = Eigen::Matrix<float, 7, 7>::Zero();
      gram.selfadjointView<Eigen::Lower>().rankUpdate(rows.leftCols(n));
      moments[c] = gram.cast<double>();
      sum_p2[c] = p2;
      counts[c] = int(n);
    }
  }
  Moments total = Moments::Zero();
  PointToPlaneEquations eq;
  for (size_t c = 0; c < blocks; ++c) {  // in block order: deterministic
    total += moments[c];
    eq.sum_p2 += sum_p2[c];
    eq.count += counts[c];
  }
  eq.H = total.topLeftCorner<6, 6>().selfadjointView<Eigen::Lower>();
  eq.b = total.block<1, 6>(6, 0).transpose();
  eq.sum_sq = total(6, 6);
  return eq;
}

}  // namespace slamkit
