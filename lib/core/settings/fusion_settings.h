#pragma once
// Point-cloud map settings (SPEC section 6).

namespace slamkit {

struct FusionSettings {
  bool enabled = true;
  // Frames back-projected: 0 = the keyframes (SPEC), n > 0 = every n-th frame.
  int frame_step = 0;
  int pixel_stride = 2;        // (ours) every n-th pixel in u and v
  double max_depth = 3.0;      // metres (ours): Kinect noise grows with z^2 (4 mm at 1.5 m)
  double voxel_size = 0.01;    // metres, PCL VoxelGrid leaf (issue: 1 cm)
  int batch_frames = 16;       // frames voxelised together before merging (bounds memory)
  // (ours) The keyframes' samples are kept from tracking's decode, up to this much memory
  // (0.54 MB a keyframe at the default stride), so that fusion need not decode them again;
  // keyframes beyond it are loaded again. 0 = fusion loads every frame.
  int keyframe_cache_mb = 1024;
  bool remove_outliers = true;     // PCL StatisticalOutlierRemoval
  int outlier_neighbours = 20;     // its mean_k
  double outlier_std_ratio = 2.0;  // its stddev_mul_thresh
  bool binary_ply = true;          // false: ASCII PLY
};

}  // namespace slamkit
