#include "fusion/map_fusion.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/stopwatch.h"
#include "fusion/ply_cloud.h"
#include "fusion/voxel_map.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

// The sampled raw pixels' ideal-pinhole rays (x/z, y/z), in sample_for_fusion's order,
// computed once per run.
struct PixelGrid {
  std::vector<Eigen::Vector2d> rays;
};

PixelGrid make_pixel_grid(const Camera& camera, int stride) {
  PixelGrid grid;
  std::vector<Eigen::Vector2d> raw;
  for (int v = 0; v < camera.height; v += stride)
    for (int u = 0; u < camera.width; u += stride) raw.emplace_back(u, v);
  const std::vector<Eigen::Vector2d> ideal =
      camera.distortion.is_zero() ? raw : camera.undistort_pixels(raw);
  grid.rays.reserve(ideal.size());
  for (const Eigen::Vector2d& p : ideal)
    grid.rays.emplace_back((p.x() - camera.cx) / camera.fx, (p.y() - camera.cy) / camera.fy);
  return grid;
}

// A frame's points placed in the grid, one list per shard of the grid.
using ShardedPoints = std::vector<std::vector<BinnedPoint>>;

// The frame's valid samples, in world coordinates, placed in `voxels`' grid, appended to their
// shards' lists in `out`; `beyond_grid` counts those the grid cannot hold.
void bin_frame(const FusionSamples& frame, const PixelGrid& grid, const Eigen::Isometry3d& T_w_c,
               double max_depth, const VoxelMap& voxels, ShardedPoints& out, size_t& beyond_grid) {
  const Eigen::Matrix3d R = T_w_c.linear();
  const Eigen::Vector3d t = T_w_c.translation();
  BinnedPoint binned;
  for (size_t i = 0; i < grid.rays.size(); ++i) {
    const double z = frame.depth[i];
    if (!(z > 0 && z <= max_depth)) continue;
    const Eigen::Vector3d p_c(grid.rays[i].x() * z, grid.rays[i].y() * z, z);
    if (voxels.bin((R * p_c + t).cast<float>(), frame.bgr[i], binned))
      out[size_t(voxels.shard_of(binned.key))].push_back(binned);
    else
      ++beyond_grid;
  }
}

void check_settings(const FusionSettings& s) {
  const auto fail = [](const std::string& what) { throw InputError("fusion settings: " + what); };
  if (s.pixel_stride < 1) fail("pixel_stride must be at least 1");
  if (!(s.max_depth > 0)) fail("max_depth must be positive");
  if (!(s.voxel_size > 0)) fail("voxel_size must be positive");
  if (s.batch_frames < 1) fail("batch_frames must be at least 1");
  if (!(s.outlier_neighbour_share >= 0 && s.outlier_neighbour_share <= 1))
    fail("outlier_neighbour_share must be within 0..1");
}

// Fails before minutes of fusion rather than after them.
void check_writable(const fs::path& ply_path) {
  std::error_code error;
  if (ply_path.has_parent_path()) fs::create_directories(ply_path.parent_path(), error);
  const fs::path temporary = temporary_path(ply_path);
  const bool ok = std::ofstream(temporary).good();
  fs::remove(temporary, error);
  if (!ok) throw_input_error(ply_path.string(), "cannot write the map here");
}

}  // namespace

FusionSamples sample_for_fusion(const cv::Mat& rgb, const cv::Mat& depth, int pixel_stride) {
  FusionSamples samples;
  const size_t per_row = size_t((depth.cols + pixel_stride - 1) / pixel_stride);
  const size_t rows = size_t((depth.rows + pixel_stride - 1) / pixel_stride);
  samples.depth.reserve(per_row * rows);
  samples.bgr.reserve(per_row * rows);
  for (int v = 0; v < depth.rows; v += pixel_stride)
    for (int u = 0; u < depth.cols; u += pixel_stride) {
      samples.depth.push_back(depth.at<float>(v, u));
      samples.bgr.push_back(rgb.at<cv::Vec3b>(v, u));
    }
  return samples;
}

FusionReport fuse_map(const TumSequence& sequence, std::vector<FusionFrame> frames,
                      const FusionSettings& settings, const fs::path& ply_path,
                      const std::function<void(size_t, size_t)>& progress) {
  Stopwatch clock;
  check_settings(settings);
  for (const FusionFrame& f : frames)
    if (f.index >= sequence.size())
      throw_input_error(sequence.folder().string(),
                        "frame " + std::to_string(f.index) + " is out of range: the sequence has " +
                            std::to_string(sequence.size()) + " frames");
  check_writable(ply_path);

  const PixelGrid grid = make_pixel_grid(sequence.camera(), settings.pixel_stride);
  VoxelMap voxels(float(settings.voxel_size), omp_get_max_threads());
  const size_t batch_size = size_t(settings.batch_frames);
  std::vector<ShardedPoints> batch(batch_size, ShardedPoints(size_t(voxels.shards())));
  FusionReport report;
  report.frames = frames.size();

  // A batch's frames are loaded (unless their samples were kept) and binned in parallel, each
  // point to its voxel's shard, then each thread adds its shard's points of the whole batch in
  // frame order, so that the sums do not depend on the thread count.
  for (size_t first = 0; first < frames.size(); first += batch_size) {
    const size_t count = std::min(batch_size, frames.size() - first);
    std::vector<std::string> errors(count);
    std::vector<size_t> beyond_grid(count, 0);
#pragma omp parallel for schedule(dynamic, 1)
    for (long i = 0; i < long(count); ++i) {
      const FusionFrame& f = frames[first + size_t(i)];
      ShardedPoints& points = batch[size_t(i)];
      for (std::vector<BinnedPoint>& shard_points : points) shard_points.clear();
      try {  // exceptions must not escape an OpenMP region
        if (f.samples) {
          bin_frame(*f.samples, grid, f.T_w_c, settings.max_depth, voxels, points,
                    beyond_grid[size_t(i)]);
        } else {
          const RgbdFrame frame = sequence.load(f.index);
          bin_frame(sample_for_fusion(frame.rgb, frame.depth, settings.pixel_stride), grid, f.T_w_c,
                    settings.max_depth, voxels, points, beyond_grid[size_t(i)]);
        }
      } catch (const std::exception& e) {
        errors[size_t(i)] = e.what();
      }
    }
    for (const std::string& error : errors)  // the earliest failing frame's, whatever the threads
      if (!error.empty()) throw InputError(error);
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
  report.after_outlier_removal = map.size();
  if (map.empty())
    throw_input_error(ply_path.string(),
                      "no point to write: no frame has valid depth within max_depth " +
                          std::to_string(settings.max_depth) + " m");

  PlyCloud out;
  out.points.reserve(map.size());
  out.colours.reserve(map.size());
  for (const VoxelCentroid& c : map) {
    out.points.push_back(c.position);
    out.colours.push_back({c.bgr[2], c.bgr[1], c.bgr[0]});
  }
  map = {};
  write_ply_cloud(ply_path, out, settings.binary_ply);
  report.seconds = clock.lap() / 1000.0;
  return report;
}

void write_camera_poses_ply(const fs::path& path, const std::vector<FusionFrame>& frames) {
  PlyCloud cloud;
  for (size_t i = 0; i < frames.size(); ++i) {
    const double s = frames.size() > 1 ? double(i) / double(frames.size() - 1) : 0.0;
    cloud.points.push_back(frames[i].T_w_c.translation().cast<float>());
    cloud.colours.push_back(
        {uint8_t(std::lround(255 * s)), 0, uint8_t(std::lround(255 * (1 - s)))});
  }
  write_ply_cloud(path, cloud, true);
}

}  // namespace slamkit
