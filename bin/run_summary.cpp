#include "bin/run_summary.h"

#include <cstdio>

#include "pipeline/run_output.h"

namespace slamkit::cli {

void print_tracking_summary(const TumSequence& seq, const RunResult& result) {
  int lost = 0, keyframes = 0, svd = 0, dense = 0;
  for (const TrackedFrame& f : result.frames) {
    lost += f.lost;
    keyframes += f.keyframe;
    svd += f.solver == PoseSolver::kSvdRansac && !f.lost;
    dense += f.solver == PoseSolver::kPointToPlane && !f.lost;
  }
  const TimingSummary timing = summarise_timing(result);
  std::printf("tracked     %zu frames of %s: %d keyframes, %d lost\n", result.frames.size(),
              seq.folder().filename().string().c_str(), keyframes, lost);
  std::printf("solvers     svd_ransac %d, point_to_plane %d, motion_model %d\n", svd, dense, lost);
  for (const std::string& line : describe_failures(result))
    std::printf("failure     %s\n", line.c_str());
  std::printf("speed       %.1f frames/s with %d threads; tracking median %.1f ms/frame\n",
              timing.frames_per_second, result.threads, timing.tracking_median_ms);
}

void StageProgress::operator()(const std::string& stage, size_t done, size_t total) {
  std::unique_ptr<Progress>& bar = bars_[stage];
  if (!bar) bar = std::make_unique<Progress>(stage, total);
  bar->update(done);
}

}  // namespace slamkit::cli
