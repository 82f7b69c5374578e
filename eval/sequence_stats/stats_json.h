#pragma once
// The sequence statistics as data (`slamkit info --stats --json FILE`). SI units: metres,
// degrees per second; shares in 0..1. Layout:
//   {"sequence", "frames", "sampled", "depth_noise": {"patches", "bins": [...], "fit": {a, b} |
//    null}, "invalid_depth": {...}, "sharpness": {"bins": [...], "correlation"},
//    "match_inliers": {...}, "per_frame": [...]}
#include <nlohmann/json.hpp>
#include <string>

#include "eval/sequence_stats/sequence_stats.h"

namespace slamkit::stats {

nlohmann::json stats_json(const SequenceStats& stats, const std::string& sequence);

}  // namespace slamkit::stats
