#pragma once
// Sums of products a[k] b[k] taken a few elements at a time, in the order Eigen's dot product
// of two float columns takes them (SSE, 4 lanes): two accumulators of 4 lanes for alternate
// groups of 4, then one added to the other, one more group of 4 if there is one, the lanes
// as (0 + 2) + (1 + 3), and the last < 4 products one by one. The dense normal equations were
// Eigen dot products over whole blocks; keeping that order (not a faster one) keeps their sums,
// and so the trajectories and the regression baselines, bit for bit. Hand-written: Eigen
// takes a dot product in one call, which would need every row of a block kept at once.
namespace slamkit {

// Four floats, added and multiplied lane by lane (GCC's vector extension: SSE on x86-64).
typedef float Float4 __attribute__((vector_size(16)));

inline Float4 load4(const float* p) {
  Float4 v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

class DotSum {
 public:
  // Adds the products of `groups` groups of 8 elements. The element count so far must be a
  // multiple of 8.
  void add_groups(const float* a, const float* b, int groups) {
    for (int g = 0; g < 8 * groups; g += 8) {
      even_ += load4(a + g) * load4(b + g);
      odd_ += load4(a + g + 4) * load4(b + g + 4);
    }
  }
  // The sum, given the last `rest` (< 8) elements.
  float finish(const float* a, const float* b, int rest) const {
    Float4 lanes = even_ + odd_;
    int k = 0;
    if (rest >= 4) lanes += load4(a) * load4(b), k = 4;
    float sum = (lanes[0] + lanes[2]) + (lanes[1] + lanes[3]);
    for (; k < rest; ++k) sum += a[k] * b[k];
    return sum;
  }

 private:
  // -0 + x is x for every x: the first group is taken as it is, as Eigen does.
  Float4 even_ = {-0.0f, -0.0f, -0.0f, -0.0f}, odd_ = even_;
};

// Four sums at once, for their independent chains of additions: add_groups of each.
inline void add_groups4(DotSum* sums, const float* const* a, const float* const* b, int groups) {
  DotSum local[4] = {sums[0], sums[1], sums[2], sums[3]};  // in registers, not memory
  for (int g = 0; g < groups; ++g)
    for (int d = 0; d < 4; ++d) local[d].add_groups(a[d] + 8 * g, b[d] + 8 * g, 1);
  for (int d = 0; d < 4; ++d) sums[d] = local[d];
}

}  // namespace slamkit
