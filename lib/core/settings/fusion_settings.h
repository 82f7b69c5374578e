#pragma once
// Point-cloud map settings (docs/method.md#map-fusion).

namespace slamkit {

struct FusionSettings {
  bool enabled = true;  // (slamkit) the map is a product of the run
  // (slamkit) Frames back-projected: 0 = the keyframes, n > 0 = every n-th frame.
  int frame_step = 0;
  int pixel_stride = 2;      // (slamkit) every n-th pixel in u and v
  double max_depth = 3.0;    // metres (slamkit): Kinect noise grows with z^2 (4 mm at 1.5 m)
  double voxel_size = 0.01;  // metres, PCL VoxelGrid leaf (slamkit)
  int batch_frames = 16;     // (slamkit) frames binned in parallel at a time (bounds memory)
  // (slamkit) Up to this much memory, the keyframes' samples are kept from tracking's decode so
  // that fusion need not decode them again; keyframes beyond it are loaded again. 0 (default):
  // fusion loads every keyframe, so that memory grows with the map and not with the keyframes
  // (0.4 MB each at the default stride).
  int keyframe_cache_mb = 0;
  // (slamkit) Outliers on the voxel grid: a voxel with fewer of its 26 neighbours occupied than
  // outlier_neighbour_share x the map's median is left out (flying pixels, specks of noise).
  // Synthetic desk 600 (median 17, so fewer than 5): map accuracy as with PCL's statistical
  // filter, which it replaced, completeness higher (docs/experiments.md).
  bool remove_outliers = true;
  double outlier_neighbour_share = 0.3;
  bool binary_ply = true;  // (slamkit) false: ASCII PLY
};

}  // namespace slamkit
