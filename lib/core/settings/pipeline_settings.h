#pragma once
// Batch engine settings (docs/method.md#architecture).

namespace slamkit {

// What trajectory files hold for a frame whose tracking failed.
enum class LostFrames {
  kOmit,         // (ORB-SLAM2) no line: a reader sees the gap
  kMotionModel,  // the constant-velocity guess (tracking.csv flags the frame as lost)
};

struct PipelineSettings {
  int threads = 0;        // (slamkit) OpenMP threads for the parallel stages; 0 = all cores
  int chunk_frames = 16;  // (slamkit) frames prepared in parallel at a time (bounds memory)
  bool evaluate = true;   // (slamkit) with groundtruth, compute ATE/RPE at the end of a run
  LostFrames lost_frames = LostFrames::kOmit;  // (ORB-SLAM2)
};

}  // namespace slamkit
