#pragma once
// Map fusion settings (docs/method.md#map-fusion).

namespace slamkit {

// How the frames become the map.
enum class MapMethod {
  kTsdf,       // a truncated signed distance field; the map is its zero-crossing surface
  kCentroids,  // each voxel's centroid of the back-projected points (the earlier map)
};

struct FusionSettings {
  bool enabled = true;  // (slamkit) the map is a product of the run
  MapMethod method = MapMethod::kTsdf;  // (slamkit) Open3D's and KinectFusion's kind of map
  // (slamkit) Frames fused: 0 = the keyframes, n > 0 = every n-th frame.
  int frame_step = 0;
  int pixel_stride = 2;      // (slamkit) every n-th pixel in u and v
  double max_depth = 3.0;    // metres (slamkit): Kinect noise grows with z^2 (4 mm at 1.5 m)
  double voxel_size = 0.01;  // metres (slamkit): Open3D's TSDF examples' 1 cm
  int batch_frames = 16;     // (slamkit) frames loaded in parallel at a time (bounds memory)
  // (slamkit) Up to this much memory, the keyframes' samples are kept from tracking's decode so
  // that fusion need not decode them again; keyframes beyond it are loaded again. 0 (default):
  // fusion loads every keyframe, so that memory grows with the map and not with the keyframes
  // (0.4 MB each at the default stride).
  int keyframe_cache_mb = 0;

  // TSDF: the signed distance is truncated at +-truncation (metres; Open3D's examples' 4 cm,
  // 4 voxels). Each measurement weighs 1/sigma^2 of the Kinect noise model at its depth and
  // incidence, relative to a head-on one at 1 m (noise_weighting; false: 1 each).
  double truncation = 0.04;
  bool noise_weighting = true;
  // (slamkit) A depth sample with a neighbour more than this share of its depth nearer or
  // farther is left out: depth edges and flying pixels (the kinect model's edge_jump).
  double edge_jump = 0.04;
  // (slamkit) Each depth sample is replaced by a plane fitted to the samples within this many
  // samples around it on the same surface (no neighbour beyond edge_jump): noise averaged,
  // slopes and edges kept. 0: raw depth.
  int smoothing_radius = 1;
  // (slamkit) The surface is kept where both voxels of a crossing weigh at least this much
  // (in head-on measurements at 1 m): a surface seen once from 3 m weighs 0.02.
  double min_weight = 0.0;
  bool mesh = false;  // (slamkit) also write mesh.ply (marching cubes, vertex colours)

  // Centroids: a voxel with fewer of its 26 neighbours occupied than outlier_neighbour_share x
  // the map's median is left out (flying pixels, specks of noise). Synthetic desk 600 (median
  // 17, so fewer than 5): map accuracy as with PCL's statistical filter, which it replaced,
  // completeness higher (docs/measurement-log/experiments.md).
  bool remove_outliers = true;
  double outlier_neighbour_share = 0.3;
  bool binary_ply = true;  // (slamkit) false: ASCII PLY
};

}  // namespace slamkit
