#pragma once
// The TSDF map (map.method tsdf; docs/method.md#map-fusion): frames integrated in order into
// a TSDF volume, the map its zero-crossing surface.
#include <functional>
#include <vector>

#include "fusion/map_fusion.h"
#include "fusion/ply_cloud.h"

namespace slamkit {

// The surface's points, normals and colours, and its triangles when settings.mesh. Fills
// report's raw_points, beyond_grid, blocks, volume_mb, points and triangles. Frees each frame's
// samples once integrated.
PlyCloud fuse_tsdf(const TumSequence& sequence, std::vector<FusionFrame>& frames,
                   const FusionSettings& settings, FusionReport& report,
                   const std::function<void(size_t, size_t)>& progress);

}  // namespace slamkit
