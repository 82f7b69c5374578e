#pragma once
// Bundle adjustment problems built from the map (stella_vslam's local_bundle_adjuster and
// global_bundle_adjuster): which keyframes move, which stay fixed, which observations count;
// the solution and the outlier verdicts are written back into the map.
#include <vector>

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

// A bundle adjustment copied out of the map: solve() needs nothing of the map, so it can run
// on another thread while tracking goes on; apply() writes the result back. The map may gain
// visible/found counts in between, but no keyframe, point or observation.
class MapBaJob {
 public:
  // Local BA around `keyframe` (ORB-SLAM2's LocalBundleAdjustment,
  // docs/method.md#local-mapping-and-bundle-adjustment): it and its covisible neighbours move
  // (keyframe 0 never does), every other keyframe observing their points is fixed.
  static MapBaJob local_window(const Map& map, int keyframe, const Camera& camera,
                               const OptimizationSettings& settings);
  // Global BA: every keyframe and point, keyframe 0 fixed. Keyframes with fewer than
  // settings.min_keyframe_points points stay out and follow their spanning-tree parent's
  // correction; so do the points only they observe, with their reference keyframe.
  static MapBaJob whole_map(const Map& map, const Camera& camera,
                            const OptimizationSettings& settings);

  void solve();
  MapAdjustment apply(Map& map) const;

 private:
  struct Link {  // a problem observation's keyframe and point in the map
    int keyframe, point;
  };
  MapBaJob(const Map& map, const std::vector<int>& free_keyframes, const Camera& camera,
           const OptimizationSettings& settings, bool local);
  // Global BA's write-back for what stayed out of it.
  void carry_along(Map& map, const std::vector<Eigen::Isometry3d>& T_w_c_before) const;

  BaProblem problem_;
  std::vector<int> keyframes_;  // problem pose -> map keyframe
  std::vector<int> points_;     // problem point -> map point
  std::vector<Link> links_;     // problem observation -> map keyframe and point
  BaIntrinsics intrinsics_;
  OptimizationSettings settings_;
  bool local_ = true;
  BaReport report_;
};

// Build, solve and apply at once.
MapAdjustment adjust_local_window(Map& map, int keyframe, const Camera& camera,
                                  const OptimizationSettings& settings);
MapAdjustment adjust_whole_map(Map& map, const Camera& camera,
                               const OptimizationSettings& settings);

}  // namespace slamkit
