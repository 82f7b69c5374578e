#pragma once
// The surface of a TSDF (docs/method.md#map-fusion): a vertex where the signed distance
// changes sign between two neighbouring voxels (linearly interpolated, as Open3D's
// extract_point_cloud), with the field's gradient as its normal and the voxels' colour; and,
// on request, the marching cubes triangles over those vertices.
#include "fusion/ply_cloud.h"
#include "fusion/tsdf_volume.h"

namespace slamkit {

// Crossings count where both voxels weigh at least min_weight (in head-on views at 1 m) and
// neither is at the truncation (|tsdf| < 0.98: a positive and a negative value there meet
// behind a surface, not on it). Points, normals and colours are filled; triangles too when
// `triangles` is set (cubes whose eight voxels are all seen and whose crossings all count).
// The same volume gives the same cloud at any thread count.
PlyCloud extract_surface(const TsdfVolume& volume, float min_weight, bool triangles);

// The cloud's triangles with only the vertices they use, renumbered in order.
PlyCloud referenced_vertices(PlyCloud mesh);

}  // namespace slamkit
