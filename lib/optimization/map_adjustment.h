#pragma once
// Bundle adjustment problems built from the map (stella_vslam's local_bundle_adjuster and
// global_bundle_adjuster): which keyframes move, which stay fixed, which observations count;
// the solution and the outlier verdicts are written back into the map.
#include "core/camera.h"
#include "core/settings/optimization_settings.h"
#include "map/map.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {

struct MapAdjustment {
  BaReport report;
  int free_keyframes = 0, fixed_keyframes = 0, points = 0, observations = 0;
  int removed_observations = 0;  // outliers unlinked from their keyframes
};

// Local BA around `keyframe` (ORBSLAM2_BACKEND.md section 3): it and its covisible neighbours
// move (keyframe 0 never does), every other keyframe observing their points is fixed.
MapAdjustment adjust_local_window(Map& map, int keyframe, const Camera& camera,
                                  const OptimizationSettings& settings);

// Global BA: every keyframe and point, keyframe 0 fixed.
MapAdjustment adjust_whole_map(Map& map, const Camera& camera,
                               const OptimizationSettings& settings);

}  // namespace slamkit
