#include "keyframes/keyframe_rule.h"

#include <algorithm>

namespace slamkit {

std::vector<size_t> keyframe_neighbours(size_t latest_keyframe, size_t current,
                                        const KeyframeSettings& settings) {
  const size_t n = size_t(std::max(0, settings.neighbour_frames));
  const size_t first = latest_keyframe >= n ? latest_keyframe - n : 0;
  const size_t last = std::min(latest_keyframe + n, current - 1);
  std::vector<size_t> indices;
  for (size_t i = first; i <= last; ++i) indices.push_back(i);
  return indices;
}

KeyframeDecision decide_keyframe(const WindowCode& current,
                                 const std::vector<const WindowCode*>& compared,
                                 int tracked_matches, int reference_matches,
                                 const KeyframeSettings& settings) {
  KeyframeDecision decision;
  for (const WindowCode* code : compared)
    decision.similarity = std::min(decision.similarity, window_similarity(current, *code));
  decision.forced_by_tracking =
      reference_matches > 0 && tracked_matches < settings.min_tracked_ratio * reference_matches;
  decision.is_keyframe =
      decision.similarity < settings.similarity_threshold || decision.forced_by_tracking;
  return decision;
}

}  // namespace slamkit
