#include "fusion/centroid_fusion.h"

#include <omp.h>

#include <algorithm>

#include "fusion/fusion_frames.h"
#include "fusion/voxel_map.h"

namespace slamkit {
namespace {

// The sampled raw pixels' ideal-pinhole rays (x/z, y/z), in sample_for_fusion's order,
// computed once per run.
std::vector<Eigen::Vector2d> pixel_rays(const Camera& camera, int stride) {
  std::vector<Eigen::Vector2d> raw;
  for (int v = 0; v < camera.height; v += stride)
    for (int u = 0; u < camera.width; u += stride) raw.emplace_back(u, v);
  const std::vector<Eigen::Vector2d> ideal =
      camera.distortion.is_zero() ? raw : camera.undistort_pixels(raw);
  std::vector<Eigen::Vector2d> rays;
  rays.reserve(ideal.size());
  for (const Eigen::Vector2d& p : ideal)
    rays.emplace_back((p.x() - camera.cx) / camera.fx, (p.y() - camera.cy) / camera.fy);
  return rays;
}

// A frame's points placed in the grid, one list per shard of the grid.
using ShardedPoints = std::vector<std::vector<BinnedPoint>>;

// The frame's valid samples, in world coordinates, placed in `voxels`' grid, appended to their
// shards' lists in `out`; `beyond_grid` counts those the grid cannot hold.
void bin_frame(const FusionSamples& frame, const std::vector<Eigen::Vector2d>& rays,
               const Eigen::Isometry3d& T_w_c, double max_depth, const VoxelMap& voxels,
               ShardedPoints& out, size_t& beyond_grid) {
  const Eigen::Matrix3d R = T_w_c.linear();
  const Eigen::Vector3d t = T_w_c.translation();
  BinnedPoint binned;
  for (size_t i = 0; i < rays.size(); ++i) {
    const double z = frame.depth[i];
    if (!(z > 0 && z <= max_depth)) continue;
    const Eigen::Vector3d p_c(rays[i].x() * z, rays[i].y() * z, z);
    if (voxels.bin((R * p_c + t).cast<float>(), frame.bgr[i], binned))
      out[size_t(voxels.shard_of(binned.key))].push_back(binned);
    else
      ++beyond_grid;
  }
}

}  // namespace

PlyCloud fuse_centroids(const TumSequence& sequence, std::vector<FusionFrame>& frames,
                        const FusionSettings& settings, FusionReport& report,
                        const std::function<void(size_t, size_t)>& progress) {
  const std::vector<Eigen::Vector2d> rays = pixel_rays(sequence.camera(), settings.pixel_stride);
  VoxelMap voxels(float(settings.voxel_size), omp_get_max_threads());
  const size_t batch_size = size_t(settings.batch_frames);
  std::vector<ShardedPoints> batch(batch_size, ShardedPoints(size_t(voxels.shards())));

  // A batch's frames are binned in parallel, each point to its voxel's shard, then each thread
  // adds its shard's points of the whole batch in frame order, so that the sums do not depend
  // on the thread count.
  for (size_t first = 0; first < frames.size(); first += batch_size) {
    const size_t count = std::min(batch_size, frames.size() - first);
    std::vector<size_t> beyond_grid(count, 0);
    for_frames_in_parallel(sequence, frames, first, count, settings.pixel_stride,
                           [&](size_t i, const FusionSamples& samples) {
                             ShardedPoints& points = batch[i - first];
                             for (std::vector<BinnedPoint>& shard_points : points)
                               shard_points.clear();
                             bin_frame(samples, rays, frames[i].T_w_c, settings.max_depth, voxels,
                                       points, beyond_grid[i - first]);
                           });
#pragma omp parallel for schedule(static, 1)
    for (int shard = 0; shard < voxels.shards(); ++shard)
      for (size_t i = 0; i < count; ++i) voxels.add(shard, batch[i][size_t(shard)]);
    for (size_t i = 0; i < count; ++i) {
      frames[first + i].samples.reset();
      for (const std::vector<BinnedPoint>& shard_points : batch[i])
        report.raw_points += shard_points.size();
      report.raw_points += beyond_grid[i];
      report.beyond_grid += beyond_grid[i];
    }
    if (progress) progress(first + count, frames.size());
  }
  batch.clear();
  report.after_voxel_grid = voxels.size();

  std::vector<VoxelCentroid> map =
      voxels.take_centroids(settings.remove_outliers ? settings.outlier_neighbour_share : 0);
  PlyCloud out;
  out.points.reserve(map.size());
  out.colours.reserve(map.size());
  for (const VoxelCentroid& c : map) {
    out.points.push_back(c.position);
    out.colours.push_back({c.bgr[2], c.bgr[1], c.bgr[0]});
  }
  report.points = out.points.size();
  return out;
}

}  // namespace slamkit
