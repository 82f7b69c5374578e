#include "tracking/dot_sums.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstring>
#include <random>

namespace slamkit {
namespace {

// The dense normal equations rely on this: taken a chunk at a time, the sums are Eigen's dot
// product of the whole columns, bit for bit (so the trajectories did not change).
TEST(DotSum, SameBitsAsEigensDotProductChunkByChunk) {
  std::mt19937 rng(7);
  std::normal_distribution<float> normal;
  for (int size : {1, 3, 4, 5, 7, 8, 9, 12, 15, 16, 17, 255, 256, 257, 1000, 3072, 4096}) {
    Eigen::VectorXf a(size), b(size);
    for (int k = 0; k < size; ++k) a[k] = normal(rng), b[k] = normal(rng);
    if (size > 2) b[1] = -0.0f;  // a signed zero among the products
    for (int chunk : {8, 64, 256}) {
      DotSum sums[4];
      const float* left[4] = {a.data(), a.data(), b.data(), a.data()};
      const float* right[4] = {b.data(), a.data(), b.data(), b.data()};
      int done = 0;
      while (size - done >= 8) {
        const int groups = std::min(chunk, size - done) / 8;
        const float* l[4] = {left[0] + done, left[1] + done, left[2] + done, left[3] + done};
        const float* r[4] = {right[0] + done, right[1] + done, right[2] + done, right[3] + done};
        add_groups4(sums, l, r, groups);
        done += 8 * groups;
      }
      const float expected[4] = {a.dot(b), a.dot(a), b.dot(b), a.dot(b)};
      for (int d = 0; d < 4; ++d) {
        const float sum = sums[d].finish(left[d] + done, right[d] + done, size - done);
        EXPECT_EQ(0, std::memcmp(&sum, &expected[d], sizeof sum)) << size << " " << chunk;
      }
    }
  }
}

}  // namespace
}  // namespace slamkit
