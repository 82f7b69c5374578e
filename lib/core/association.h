#pragma once
// Timestamp association, the TUM benchmark's rule (associate.py): every pair (a, b) with
// |a - (b + offset)| < max_diff is a candidate; candidates are taken greedily by smallest
// difference (ties by a, then b), each stamp used at most once; the result is sorted by a.
#include <cstddef>
#include <utility>
#include <vector>

namespace slamkit {

struct IndexPair {
  size_t first;   // index into the first (sorted) stamp list
  size_t second;  // index into the second (sorted) stamp list
};

// Both lists must be sorted ascending.
std::vector<IndexPair> associate_greedy(const std::vector<double>& first,
                                        const std::vector<double>& second, double max_diff,
                                        double offset = 0.0);

}  // namespace slamkit
