#pragma once
// One split of the vocabulary tree: k-medians clustering of binary descriptors under the
// Hamming distance, seeded by k-means++ (docs/method.md#loop-closing).
#include <cstdint>
#include <vector>

#include "loop/binary_descriptor.h"

namespace slamkit {

struct Clustering {
  std::vector<Descriptor> centres;  // no empty cluster among them
  std::vector<int> assignment;      // per member: index into centres, its nearest centre
};

// Clusters `members` (32-byte descriptors) into at most k clusters: k-means++ seeding (each
// next seed drawn with probability proportional to the squared distance to the nearest seed,
// from a generator seeded by `seed`), then up to `max_iterations` rounds of majority centres
// and nearest-centre assignment, stopping early once no assignment changes. Fewer than k
// distinct members give one cluster each. Deterministic for a given input and seed at any
// thread count: only integer work is shared among threads.
Clustering k_medians(const std::vector<const uint8_t*>& members, int k, int max_iterations,
                     uint64_t seed);

}  // namespace slamkit
