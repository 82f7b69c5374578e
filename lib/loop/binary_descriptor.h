#pragma once
// 256-bit ORB descriptors as the vocabulary stores them, and the per-bit majority that makes a
// cluster's centre (the k-medians centre under the Hamming distance).
#include <cstdint>
#include <vector>

#include "features/descriptor.h"

namespace slamkit {

// Bit b of the result is set when more than half of `members` have it set (ties give 0, so the
// majority of two different descriptors is their AND). `members` must not be empty.
Descriptor majority_descriptor(const std::vector<const uint8_t*>& members);

}  // namespace slamkit
