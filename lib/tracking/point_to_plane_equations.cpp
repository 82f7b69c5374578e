#include "tracking/point_to_plane_equations.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tracking/dot_sums.h"

namespace slamkit {
namespace {

// Current pixels per block. Fixed, so that each block's sums, and the order in which they
// are added, do not depend on the thread count.
constexpr long kPixelsPerBlock = 4096;
// Pixels a pass handles at once: a chunk's columns stay in L1 from one pass to the next.
constexpr int kChunk = 256;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The pose and camera in single precision (twice the SIMD width of double, and the depth
// noise is ~1e4 times the rounding), and what projective association accepts: the previous
// pixel inside the box, and there a point no farther than max_pair_distance with a normal
// within max_normal_angle_deg.
struct Association {
  float R[3][3], t[3];
  float fx, fy, cx, cy;  // cx, cy + 0.5: the nearest pixel by truncation
  float x0, x1, y0, y1;
  float max_sq, min_cos;
};

// One chunk's columns, each pass a plain loop over them (over the chunk's first n pixels:
// the block's last chunk may be shorter).
struct Chunk {
  // The current points moved into the previous camera and their normals rotated likewise,
  // and the previous pixel they project to (u = -1: none).
  alignas(16) float p[3][kChunk], n[3][kChunk];
  alignas(16) int u[kChunk], v[kChunk];
  // There, the previous point and normal (NaN normal where there is none: fails the angle
  // test).
  alignas(16) float q[3][kChunk], N[3][kChunk];
  // Per pair h = (N x p, N), m = (p - q).N and |p|^2, zero without a pair; then ones.
  alignas(16) float rows[9][kChunk];
};

// p' = R p + t, n' = R n and the pixel p' falls in, for `size` pixels of `row` from column
// u0 on, stored from `offset` in the chunk.
void move_and_project_row(const Surface& curr, int row, int u0, int size, int offset,
                          const Association& a, Chunk& c) {
  const long begin = curr.index(u0, row);
  const float *z = curr.pixels.col(0).data() + begin, *nx = curr.pixels.col(1).data() + begin,
              *ny = curr.pixels.col(2).data() + begin, *nz = curr.pixels.col(3).data() + begin;
  const float* xs = curr.x_factors.data() + u0;
  const float y_factor = curr.y_factors[size_t(row)];
  const auto& R = a.R;
#pragma omp simd
  for (int k = 0; k < size; ++k) {
    const float x = xs[k] * z[k], y = y_factor * z[k];
    const float px = R[0][0] * x + R[0][1] * y + R[0][2] * z[k] + a.t[0];
    const float py = R[1][0] * x + R[1][1] * y + R[1][2] * z[k] + a.t[1];
    const float pz = R[2][0] * x + R[2][1] * y + R[2][2] * z[k] + a.t[2];
    const int o = offset + k;
    c.p[0][o] = px, c.p[1][o] = py, c.p[2][o] = pz;
    c.n[0][o] = R[0][0] * nx[k] + R[0][1] * ny[k] + R[0][2] * nz[k];
    c.n[1][o] = R[1][0] * nx[k] + R[1][1] * ny[k] + R[1][2] * nz[k];
    c.n[2][o] = R[2][0] * nx[k] + R[2][1] * ny[k] + R[2][2] * nz[k];
    // A point without depth is NaN and fails every comparison.
    const float u = a.fx * px / pz + a.cx, v = a.fy * py / pz + a.cy;
    const bool inside = (pz > 0) & (u >= a.x0) & (u < a.x1) & (v >= a.y0) & (v < a.y1);
    // Truncation is the floor for u, v >= 0.
    c.u[o] = int(inside ? u : -1.0f), c.v[o] = int(inside ? v : 0.0f);
  }
}

// The same for pixels [begin, begin + size), row by row (a chunk spans at most a few rows).
void move_and_project(const Surface& curr, long begin, int size, const Association& a, Chunk& c) {
  for (int done = 0; done < size;) {
    const long i = begin + done;
    const int row = int(i / curr.width), u0 = int(i % curr.width);
    const int n = std::min(size - done, curr.width - u0);
    move_and_project_row(curr, row, u0, n, done, a, c);
    done += n;
  }
}

// The previous point and normal at each pixel found: a gather, so point by point, by hand.
void gather(const Surface& prev, int size, Chunk& c) {
  const float *Z = prev.pixels.col(0).data(), *NX = prev.pixels.col(1).data(),
              *NY = prev.pixels.col(2).data(), *NZ = prev.pixels.col(3).data();
  const float *xs = prev.x_factors.data(), *ys = prev.y_factors.data();
  for (int k = 0; k < size; ++k) {
    const bool none = c.u[k] < 0;
    const int u = none ? 0 : c.u[k], v = c.v[k], j = prev.index(u, v);
    c.q[0][k] = xs[u] * Z[j], c.q[1][k] = ys[v] * Z[j], c.q[2][k] = Z[j];
    c.N[0][k] = none ? kNaN : NX[j], c.N[1][k] = NY[j], c.N[2][k] = NZ[j];
  }
}

// The pair test and each pair's rows, without branches (a pixel without a pair, here or
// there, has NaN in it and fails a test). Returns the number of pairs.
int linearise(const Association& a, int size, Chunk& c) {
  int pairs = 0;
#pragma omp simd reduction(+ : pairs)
  for (int k = 0; k < size; ++k) {
    const float dx = c.p[0][k] - c.q[0][k], dy = c.p[1][k] - c.q[1][k], dz = c.p[2][k] - c.q[2][k];
    const bool paired =
        (dx * dx + dy * dy + dz * dz <= a.max_sq) &
        (c.n[0][k] * c.N[0][k] + c.n[1][k] * c.N[1][k] + c.n[2][k] * c.N[2][k] >= a.min_cos);
    const float px = paired ? c.p[0][k] : 0.0f, py = paired ? c.p[1][k] : 0.0f,
                pz = paired ? c.p[2][k] : 0.0f;
    const float Nx = paired ? c.N[0][k] : 0.0f, Ny = paired ? c.N[1][k] : 0.0f,
                Nz = paired ? c.N[2][k] : 0.0f;
    c.rows[0][k] = Ny * pz - Nz * py;
    c.rows[1][k] = Nz * px - Nx * pz;
    c.rows[2][k] = Nx * py - Ny * px;
    c.rows[3][k] = Nx, c.rows[4][k] = Ny, c.rows[5][k] = Nz;
    c.rows[6][k] = paired ? dx * Nx + dy * Ny + dz * Nz : 0.0f;
    c.rows[7][k] = px * px + py * py + pz * pz;
    pairs += paired;
  }
  return pairs;
}

// One block's sums: the Gram matrix of (h, m), sum |p|^2 and the pairs.
struct BlockSums {
  Eigen::Matrix<double, 7, 7> gram = Eigen::Matrix<double, 7, 7>::Zero();
  double sum_p2 = 0;
  int count = 0;
};

// The sums a block needs, as rows of a chunk: the Gram matrix's lower triangle (i, k), then
// sum |p|^2 as row 7 times ones.
constexpr int kSums = 29;
struct SumTerms {
  int i[kSums], k[kSums];
};
constexpr SumTerms sum_terms() {
  SumTerms t{};
  int s = 0;
  for (int i = 0; i < 7; ++i)
    for (int k = 0; k <= i; ++k) t.i[s] = i, t.k[s] = k, ++s;
  t.i[s] = 7, t.k[s] = 8;  // row 8: ones
  return t;
}

BlockSums block_sums(const Surface& prev, const Surface& curr, long begin, long size,
                     const Association& a) {
  constexpr SumTerms terms = sum_terms();
  Chunk c;
  std::fill_n(c.rows[8], kChunk, 1.0f);
  const float *left[kSums], *right[kSums];
  for (int s = 0; s < kSums; ++s) left[s] = c.rows[terms.i[s]], right[s] = c.rows[terms.k[s]];
  DotSum dots[kSums];
  BlockSums sums;
  int n = 0;
  for (long offset = 0; offset < size; offset += n) {
    n = int(std::min<long>(kChunk, size - offset));
    move_and_project(curr, begin + offset, n, a, c);
    gather(prev, n, c);
    sums.count += linearise(a, n, c);
    int s = 0;
    for (; s + 4 <= kSums; s += 4) add_groups4(dots + s, left + s, right + s, n / 8);
    for (; s < kSums; ++s) dots[s].add_groups(left[s], right[s], n / 8);
  }
  // Only the last chunk may end with a part of a group: its elements finish the sums.
  const int last = 8 * (n / 8);
  for (int s = 0; s < kSums - 1; ++s)
    sums.gram(terms.i[s], terms.k[s]) =
        double(dots[s].finish(left[s] + last, right[s] + last, n - last));
  sums.sum_p2 =
      double(dots[kSums - 1].finish(left[kSums - 1] + last, right[kSums - 1] + last, n - last));
  return sums;
}

}  // namespace

PointToPlaneEquations point_to_plane_equations(const Surface& prev, const Surface& curr,
                                               const cv::Rect& box,
                                               const Eigen::Isometry3d& T_prev_curr,
                                               const PointToPlaneSettings& settings) {
  Association a;
  const Eigen::Matrix3f R = T_prev_curr.linear().cast<float>();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) a.R[r][k] = R(r, k);
    a.t[r] = float(T_prev_curr.translation()(r));
  }
  const Camera& cam = prev.camera;
  a.fx = float(cam.fx), a.fy = float(cam.fy);
  a.cx = float(cam.cx + 0.5), a.cy = float(cam.cy + 0.5);
  a.x0 = float(box.x), a.x1 = float(box.x + box.width);
  a.y0 = float(box.y), a.y1 = float(box.y + box.height);
  a.max_sq = float(settings.max_pair_distance * settings.max_pair_distance);
  a.min_cos = float(std::cos(settings.max_normal_angle_deg * M_PI / 180));

  const long pixels = curr.pixels.rows();
  const long blocks = (pixels + kPixelsPerBlock - 1) / kPixelsPerBlock;
  std::vector<BlockSums> sums(static_cast<size_t>(blocks));
#pragma omp parallel for schedule(static)
  for (long b = 0; b < blocks; ++b) {
    const long begin = b * kPixelsPerBlock;
    sums[size_t(b)] = block_sums(prev, curr, begin, std::min(kPixelsPerBlock, pixels - begin), a);
  }
  Eigen::Matrix<double, 7, 7> total = Eigen::Matrix<double, 7, 7>::Zero();
  PointToPlaneEquations eq;
  for (const BlockSums& s : sums) {  // in block order: deterministic
    total += s.gram;
    eq.sum_p2 += s.sum_p2;
    eq.count += s.count;
  }
  total.triangularView<Eigen::StrictlyUpper>() = total.transpose();
  eq.H = total.topLeftCorner<6, 6>();
  eq.b = total.block<1, 6>(6, 0).transpose();
  eq.sum_sq = total(6, 6);
  return eq;
}

}  // namespace slamkit
