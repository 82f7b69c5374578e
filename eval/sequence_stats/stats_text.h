#pragma once
// The sequence statistics as the lines `slamkit info --stats` prints.
#include <cstdio>

#include "eval/sequence_stats/sequence_stats.h"

namespace slamkit::stats {

void print_stats(const SequenceStats& stats, std::FILE* out);

}  // namespace slamkit::stats
