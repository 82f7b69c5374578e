#pragma once
// Batch engine settings.

namespace slamkit {

struct PipelineSettings {
  int threads = 0;         // OpenMP threads for the parallel stages; 0 = all cores
  int chunk_frames = 32;   // frames prepared in parallel at a time (bounds memory)
  bool evaluate = true;    // with groundtruth, compute ATE/RPE at the end of a run
};

}  // namespace slamkit
