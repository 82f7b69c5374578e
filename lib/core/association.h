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

// associate_greedy weighs every pair within max_diff, so stamps crowded together (one stamp
// repeated, or stamps that are not in seconds) make its time and memory quadratic. Callers
// refuse lists with more candidate pairs than this many per stamp on average; real recordings
// have a handful (a 1 kHz groundtruth against 30 Hz frames: about 40).
constexpr size_t kMaxCandidatesPerStamp = 64;

// The pairs with |a - (b + offset)| <= window, counted in O(n log m) without listing them.
// Both lists sorted ascending.
size_t count_candidate_pairs(const std::vector<double>& first, const std::vector<double>& second,
                             double window, double offset = 0.0);
// True when count_candidate_pairs exceeds kMaxCandidatesPerStamp per stamp of both lists.
bool too_crowded_to_associate(const std::vector<double>& first, const std::vector<double>& second,
                              double window, double offset = 0.0);

// Both lists must be sorted ascending.
std::vector<IndexPair> associate_greedy(const std::vector<double>& first,
                                        const std::vector<double>& second, double max_diff,
                                        double offset = 0.0);

}  // namespace slamkit
