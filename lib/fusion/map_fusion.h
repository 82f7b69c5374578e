#pragma once
// The map (docs/method.md#map-fusion): frames fused with their final poses into a TSDF whose
// surface is the map (or each voxel's centroid of the back-projected points), written as PLY.
// PCL appears only in this module's .cpp files (marching cubes tables): callers never see it.
#include <Eigen/Geometry>
#include <filesystem>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/fusion_settings.h"
#include "io/tum_sequence.h"

namespace slamkit {

// A frame's pixels as fusion samples them: every pixel_stride-th pixel in u and v, row by row,
// depth in metres and BGR colour. Taken from the images tracking decoded anyway, it spares
// fusion decoding the frame again (2 of the 4 s of fusion on synthetic desk 600).
struct FusionSamples {
  std::vector<float> depth;
  std::vector<cv::Vec3b> bgr;
  size_t bytes() const { return depth.size() * sizeof(float) + bgr.size() * sizeof(cv::Vec3b); }
};
FusionSamples sample_for_fusion(const cv::Mat& rgb, const cv::Mat& depth, int pixel_stride);

struct FusionFrame {
  size_t index = 0;  // frame of the sequence (TumSequence::load)
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  // The frame's samples (sample_for_fusion, same pixel_stride) if kept; null: loaded again.
  std::shared_ptr<const FusionSamples> samples;
};

struct FusionReport {
  MapMethod method = MapMethod::kTsdf;
  size_t frames = 0;
  size_t raw_points = 0;   // depth samples taken (centroids: back-projected, before any filter)
  size_t beyond_grid = 0;  // of those, so far from the origin that no voxel holds them
  size_t points = 0;       // written to the map
  // Centroids: occupied voxels, before outlier removal.
  size_t after_voxel_grid = 0;
  // TSDF: blocks of 8^3 voxels allocated, their memory; triangles in the mesh when one is made.
  size_t blocks = 0;
  double volume_mb = 0;
  size_t triangles = 0;
  double seconds = 0;
};

// Fuses the frames into a map and writes it as `ply_path` (binary unless !settings.binary_ply),
// and the mesh as `mesh_path` when settings.mesh (TSDF only). The output is the same at any
// thread count. progress(done, total) is called on the calling thread. Frames are loaded
// (unless their samples were kept) settings.batch_frames at a time in parallel, and each
// frame's samples are released once fused.
//
// TSDF (tsdf_frame.h, tsdf_volume.h, tsdf_surface.h): each frame's samples, in ideal pinhole
// geometry, edges left out, weighted by the depth noise model, integrated in frame order; the
// map is the field's zero-crossing surface with normals and colours.
// Centroids: each sample back-projected (every settings.pixel_stride-th raw pixel undistorted
// once, depth 0 or beyond settings.max_depth skipped) into a voxel grid of settings.voxel_size
// that keeps each voxel's sums (voxel_map.h), so memory grows with the voxels, not the frames;
// then every voxel's centroid and mean colour, leaving out voxels with few occupied neighbours.
//
// The PLY is written as ply_cloud.h describes, through a temporary file renamed into place.
// Throws InputError naming the sequence folder for a frame index out of range, the image for
// an unreadable frame, ply_path when it cannot be written (checked before any work) or when
// no frame has valid depth, and "fusion settings" for a setting out of range.
FusionReport fuse_map(const TumSequence& sequence, std::vector<FusionFrame> frames,
                      const FusionSettings& settings, const std::filesystem::path& ply_path,
                      const std::filesystem::path& mesh_path = {},
                      const std::function<void(size_t, size_t)>& progress = {});

// The camera centres of `frames` as a small binary PLY (one vertex each, coloured from blue
// at the first frame to red at the last), to open together with map.ply in a viewer: e.g.
// `slamkit` runs may write keyframe_centres.ply beside map.ply. Throws like write_ply_cloud,
// so an empty list is an error.
void write_camera_poses_ply(const std::filesystem::path& path,
                            const std::vector<FusionFrame>& frames);

}  // namespace slamkit
