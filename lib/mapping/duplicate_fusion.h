#pragma once
// Duplicate fusion (ORB-SLAM2's Fuse, docs/method.md#local-mapping-and-bundle-adjustment): map
// points projected into a keyframe are merged with the point its matching keypoint already
// observes (the better-observed one survives), or give that keypoint its observation.
#include <vector>

#include "core/camera.h"
#include "core/settings/mapping_settings.h"
#include "map/map.h"

namespace slamkit {

struct FusionGates {
  double radius = 3;      // pixels at level 0, times the predicted level's scale
  int max_distance = 50;  // Hamming
  double min_view_cos = 0.5;
  double chi2_2d = 5.991, chi2_3d = 7.815;
  double virtual_bf = 40;  // for the depth term of the reprojection gate
};

// Projects `points` into `keyframe` and fuses them; returns, once per fusion, the point that
// gained the observations (the survivor of a merge, or the point newly linked).
std::vector<int> fuse_into_keyframe(Map& map, int keyframe, const std::vector<int>& points,
                                    const Camera& camera, const FusionGates& gates);

}  // namespace slamkit
