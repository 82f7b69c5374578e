#include "tracking/point_to_plane_equations.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slamkit {
namespace {

// Current pixels per block. Fixed, so that each block's sums, and the order in which they
// are added, do not depend on the thread count.
constexpr long kPixelsPerBlock = 4096;

using Columns3 = Eigen::Matrix<float, Eigen::Dynamic, 3>;
using Moments = Eigen::Matrix<double, 7, 7>;

// One block's work, a column per quantity, so that Eigen evaluates each step over the whole
// block with SIMD. Allocated once per thread.
struct BlockWork {
  // The current points moved into the previous camera and their normals rotated likewise;
  // the previous pixel they project to (+0.5: the nearest one by truncation).
  Columns3 p, n;
  Eigen::ArrayXf u, v;
  // Per pair, the previous point and normal. A pixel without a pair gets p = q = N = 0
  // (its point may be NaN), which zeroes its row.
  Columns3 q, N;
  Eigen::Matrix<float, Eigen::Dynamic, 7> rows;  // (h, m) of the linearised cost
};

// What projective association accepts: the previous pixel inside the box, and there a point
// no farther than max_pair_distance with a normal within max_normal_angle_deg.
struct Gate {
  float x0, x1, y0, y1;
  float max_sq, min_cos;
};

// Pairs each point of the block with the previous pixel it projects to. A gather, so point
// by point, by hand, without branches: a pixel without a normal, here or there, has NaN in
// it and fails the angle test. Returns the number of pairs.
int associate(const Surface& prev, const Gate& gate, long size, BlockWork& work) {
  const float *X = prev.pixels.col(0).data(), *Y = prev.pixels.col(1).data(),
              *Z = prev.pixels.col(2).data();
  const float *NX = prev.pixels.col(3).data(), *NY = prev.pixels.col(4).data(),
              *NZ = prev.pixels.col(5).data();
  float *px = work.p.col(0).data(), *py = work.p.col(1).data(), *pz = work.p.col(2).data();
  const float *nx = work.n.col(0).data(), *ny = work.n.col(1).data(), *nz = work.n.col(2).data();
  work.q.resize(size, 3);
  work.N.resize(size, 3);
  float *qx = work.q.col(0).data(), *qy = work.q.col(1).data(), *qz = work.q.col(2).data();
  float *Nx = work.N.col(0).data(), *Ny = work.N.col(1).data(), *Nz = work.N.col(2).data();
  int pairs = 0;
  for (long k = 0; k < size; ++k) {
    const float u = work.u(k), v = work.v(k);
    const bool inside =
        (pz[k] > 0) & (u >= gate.x0) & (u < gate.x1) & (v >= gate.y0) & (v < gate.y1);
    const int j = inside ? prev.index(int(u), int(v)) : 0;
    const float dx = px[k] - X[j], dy = py[k] - Y[j], dz = pz[k] - Z[j];
    const bool paired = inside & (dx * dx + dy * dy + dz * dz <= gate.max_sq) &
                        (nx[k] * NX[j] + ny[k] * NY[j] + nz[k] * NZ[j] >= gate.min_cos);
    qx[k] = paired ? X[j] : 0.0f;
    qy[k] = paired ? Y[j] : 0.0f;
    qz[k] = paired ? Z[j] : 0.0f;
    Nx[k] = paired ? NX[j] : 0.0f;
    Ny[k] = paired ? NY[j] : 0.0f;
    Nz[k] = paired ? NZ[j] : 0.0f;
    px[k] = paired ? px[k] : 0.0f;
    py[k] = paired ? py[k] : 0.0f;
    pz[k] = paired ? pz[k] : 0.0f;
    pairs += paired;
  }
  return pairs;
}

}  // namespace

PointToPlaneEquations point_to_plane_equations(const Surface& prev, const Surface& curr,
                                               const cv::Rect& box,
                                               const Eigen::Isometry3d& T_prev_curr,
                                               const PointToPlaneSettings& settings) {
  const long pixels = curr.pixels.rows();
  const long blocks = (pixels + kPixelsPerBlock - 1) / kPixelsPerBlock;
  std::vector<Moments> moments(static_cast<size_t>(blocks));
  std::vector<double> sum_p2(static_cast<size_t>(blocks));
  std::vector<int> counts(static_cast<size_t>(blocks));
  // Single precision per pair (twice the SIMD width of double, and the depth noise is ~1e4
  // times the rounding); each block's sums go to double before they are added up.
  const Eigen::Matrix3f R = T_prev_curr.linear().cast<float>();
  const Eigen::Vector3f t = T_prev_curr.translation().cast<float>();
  const Camera& cam = prev.camera;
  const float fx = float(cam.fx), fy = float(cam.fy);
  const float cx = float(cam.cx + 0.5), cy = float(cam.cy + 0.5);
  const Gate gate{float(box.x),
                  float(box.x + box.width),
                  float(box.y),
                  float(box.y + box.height),
                  float(settings.max_pair_distance * settings.max_pair_distance),
                  float(std::cos(settings.max_normal_angle_deg * M_PI / 180))};
#pragma omp parallel
  {
    BlockWork work;
#pragma omp for schedule(static)
    for (long c = 0; c < blocks; ++c) {
      const long begin = c * kPixelsPerBlock;
      const long size = std::min(kPixelsPerBlock, pixels - begin);
      const auto block = curr.pixels.middleRows(begin, size);
      // p' = R p + t and n' = R n, a column (coordinate) at a time.
      work.p.resize(size, 3);
      work.n.resize(size, 3);
      for (int r = 0; r < 3; ++r) {
        work.p.col(r).array() = R(r, 0) * block.col(0).array() + R(r, 1) * block.col(1).array() +
                                R(r, 2) * block.col(2).array() + t(r);
        work.n.col(r) = R(r, 0) * block.col(3) + R(r, 1) * block.col(4) + R(r, 2) * block.col(5);
      }
      work.u = fx * work.p.col(0).array() / work.p.col(2).array() + cx;
      work.v = fy * work.p.col(1).array() / work.p.col(2).array() + cy;
      counts[size_t(c)] = associate(prev, gate, size, work);
      // h = (N x p, N), m = (p - q).N, for the whole block at once.
      const auto px = work.p.col(0).array(), py = work.p.col(1).array(), pz = work.p.col(2).array();
      const auto Nx = work.N.col(0).array(), Ny = work.N.col(1).array(), Nz = work.N.col(2).array();
      work.rows.resize(size, 7);
      work.rows.col(0).array() = Ny * pz - Nz * py;
      work.rows.col(1).array() = Nz * px - Nx * pz;
      work.rows.col(2).array() = Nx * py - Ny * px;
      work.rows.middleCols<3>(3) = work.N;
      work.rows.col(6).array() = (px - work.q.col(0).array()) * Nx +
                                 (py - work.q.col(1).array()) * Ny +
                                 (pz - work.q.col(2).array()) * Nz;
      // The Gram matrix of the rows: 28 dot products (Eigen's vectorised dot).
      Moments& gram = moments[size_t(c)];
      for (int i = 0; i < 7; ++i)
        for (int k = 0; k <= i; ++k)
          gram(i, k) = gram(k, i) = double(work.rows.col(i).dot(work.rows.col(k)));
      sum_p2[size_t(c)] = double((px.square() + py.square() + pz.square()).sum());
    }
  }
  Moments total = Moments::Zero();
  PointToPlaneEquations eq;
  for (long c = 0; c < blocks; ++c) {  // in block order: deterministic
    total += moments[size_t(c)];
    eq.sum_p2 += sum_p2[size_t(c)];
    eq.count += counts[size_t(c)];
  }
  eq.H = total.topLeftCorner<6, 6>();
  eq.b = total.block<1, 6>(6, 0).transpose();
  eq.sum_sq = total(6, 6);
  return eq;
}

}  // namespace slamkit
