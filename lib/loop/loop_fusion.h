#pragma once
// Loop fusion (ORB-SLAM2's SearchAndFuse in CorrectLoop, docs/method.md#loop-closing): once
// the map is corrected, the two ends of a loop still hold two copies of the same scene, one
// made at the start and one at the end. The points around the loop keyframe are projected into
// the keyframe that found the loop and its neighbours and fused with the copies there, so that
// the global BA that follows ties both ends together through shared observations.
#include <vector>

#include "core/camera.h"
#include "core/settings/settings.h"
#include "map/map.h"
#include "optimization/map_pose_graph.h"

namespace slamkit {

// Returns the number of fusions (points merged or observations gained).
int fuse_loop_points(Map& map, const std::vector<LoopConstraint>& loops, const Camera& camera,
                     const Settings& settings);

}  // namespace slamkit
