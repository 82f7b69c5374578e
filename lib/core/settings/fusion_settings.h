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
  int batch_frames = 16;     // (slamkit) frames voxelised together before merging (bounds memory)
  // (slamkit) The keyframes' samples are kept from tracking's decode, up to this much memory,
  // so that fusion need not decode them again; keyframes beyond it are loaded again.
  // 0 = fusion loads every frame.
  int keyframe_cache_mb = 1024;
  bool remove_outliers = true;     // (slamkit) PCL StatisticalOutlierRemoval
  int outlier_neighbours = 20;     // (slamkit) its mean_k
  double outlier_std_ratio = 2.0;  // (slamkit) its stddev_mul_thresh
  bool binary_ply = true;          // (slamkit) false: ASCII PLY
};

}  // namespace slamkit
