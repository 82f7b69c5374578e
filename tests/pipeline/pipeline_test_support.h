#pragma once
// What the pipeline tests share: synthetic sequences (support/synthetic_sequence.h), the
// benchmark's ATE, and file comparison.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "eval/metrics/association.h"
#include "eval/metrics/ate.h"
#include "pipeline/batch_engine.h"
#include "support/synthetic_sequence.h"

namespace slamkit::test {

// ATE RMSE (metres) as the benchmark computes it; every frame must have groundtruth.
inline double ate_rmse(const Trajectory& gt, const Trajectory& estimate) {
  EXPECT_EQ(eval::associate(gt, estimate, eval::AssociationOptions{}).size(), estimate.size())
      << "every frame must have groundtruth";
  return eval::ate_rmse(gt, estimate);
}

inline int count_lost(const RunResult& r) {
  int lost = 0;
  for (const TrackedFrame& f : r.frames) lost += f.lost;
  return lost;
}

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace slamkit::test
