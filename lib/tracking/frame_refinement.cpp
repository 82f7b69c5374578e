#include "tracking/frame_refinement.h"

#include "core/pose.h"
#include "tracking/motion_only_ba.h"

namespace slamkit {

int refine_frames(const Map& map, const Camera& camera, const MotionBaSettings& settings,
                  std::vector<TrackedFrame>& frames) {
  int refined = 0;
#pragma omp parallel for schedule(dynamic, 16) reduction(+ : refined)
  for (size_t i = 0; i < frames.size(); ++i) {
    TrackedFrame& frame = frames[i];
    std::vector<PointObservation> observations;
    observations.reserve(frame.matched.size());
    for (const MatchedKeypoint& m : frame.matched) {
      const MapPoint& point = map.point(m.point_id);
      if (point.bad) continue;
      observations.push_back({point.p_w, {m.u, m.v}, m.depth, m.sigma});
    }
    std::vector<MatchedKeypoint>().swap(frame.matched);
    if (observations.empty()) continue;
    const PoseRefinement solved = motion_only_ba(observations, camera, frame.T_w_c, settings);
    if (!solved.ok) continue;
    frame.T_w_c = orthonormalised(solved.T_w_c);
    ++refined;
  }
  return refined;
}

}  // namespace slamkit
