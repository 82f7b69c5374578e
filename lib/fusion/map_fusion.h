#pragma once
// The point-cloud map (docs/method.md#map-fusion): frames back-projected with their final
// poses into one coloured cloud, down-sampled on a voxel grid, isolated voxels left out,
// written as PLY. The only module that includes PCL (in its .cpp files: callers never see PCL
// types).
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
  size_t frames = 0;
  size_t raw_points = 0;        // back-projected, before any filter
  size_t beyond_grid = 0;       // of those, so far from the origin that no voxel holds them
  size_t after_voxel_grid = 0;  // occupied voxels
  size_t after_outlier_removal = 0;
  double seconds = 0;
};

// Back-projects the frames (their samples, or loaded again from the sequence, settings.batch_frames
// at a time in parallel) into a voxel grid of settings.voxel_size that keeps each voxel's sums
// (voxel_map.h), so memory grows with the voxels, not the frames (each frame's samples are
// released once binned); then takes every voxel's
// centroid and mean colour, leaves out voxels with few occupied neighbours, and writes `ply_path`
// (binary unless !settings.binary_ply). The output is the same at any thread count. progress(done,
// total) is called on the calling thread.
//
// Every settings.pixel_stride-th raw pixel (u, v) is undistorted once for the whole grid
// (the depth is registered to colour in the raw lens geometry), so a point is
// z * ((u' - cx) / fx, (v' - cy) / fy, 1) at the ideal pixel (u', v'); depth 0 or beyond
// settings.max_depth is skipped. The PLY is written as ply_cloud.h describes, through a
// temporary file renamed into place.
// Throws InputError naming the sequence folder for a frame index out of range, the image for
// an unreadable frame, ply_path when it cannot be written (checked before any work) or when
// no frame has valid depth, and "fusion settings" for a setting out of range.
FusionReport fuse_map(const TumSequence& sequence, std::vector<FusionFrame> frames,
                      const FusionSettings& settings, const std::filesystem::path& ply_path,
                      const std::function<void(size_t, size_t)>& progress = {});

// The camera centres of `frames` as a small binary PLY (one vertex each, coloured from blue
// at the first frame to red at the last), to open together with map.ply in a viewer: e.g.
// `slamkit` runs may write keyframe_centres.ply beside map.ply. Throws like write_ply_cloud,
// so an empty list is an error.
void write_camera_poses_ply(const std::filesystem::path& path,
                            const std::vector<FusionFrame>& frames);

}  // namespace slamkit
