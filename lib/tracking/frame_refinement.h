#pragma once
// Frame refinement (docs/method.md#frame-refinement): after the back end, each frame that is not
// a keyframe solves its pose again by motion-only BA on the inliers its tracking kept, against
// the points as global BA left them. Tracking solved it against young points (seen from a few
// keyframes, not yet adjusted), and re-anchoring carries over only its reference keyframe's
// correction; a keyframe's pose comes out of BA itself.
#include <vector>

#include "core/camera.h"
#include "core/settings/tracking_settings.h"
#include "map/map.h"
#include "tracking/tracked_frame.h"

namespace slamkit {

// Every frame with matches (TrackedFrame::matched) starts from its re-anchored pose and takes
// the refined one when motion-only BA succeeds (at least settings.min_inliers inliers); points
// culled or fused away since tracking are left out. The matches are released. Returns how many
// frames moved. Frames are independent: the result is the same for any thread count.
int refine_frames(const Map& map, const Camera& camera, const MotionBaSettings& settings,
                  std::vector<TrackedFrame>& frames);

}  // namespace slamkit
