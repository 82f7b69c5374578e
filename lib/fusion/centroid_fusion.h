#pragma once
// The centroid map (map.method centroids; docs/method.md#map-fusion): every sample
// back-projected into a voxel grid that keeps each voxel's sums, then each voxel's centroid
// and mean colour, voxels with few occupied neighbours left out.
#include <functional>
#include <vector>

#include "fusion/map_fusion.h"
#include "fusion/ply_cloud.h"

namespace slamkit {

// Fills report's raw_points, beyond_grid, after_voxel_grid and points. Frees each frame's
// samples once binned.
PlyCloud fuse_centroids(const TumSequence& sequence, std::vector<FusionFrame>& frames,
                        const FusionSettings& settings, FusionReport& report,
                        const std::function<void(size_t, size_t)>& progress);

}  // namespace slamkit
