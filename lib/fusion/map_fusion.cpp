#include "fusion/map_fusion.h"

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/stopwatch.h"
#include "fusion/centroid_fusion.h"
#include "fusion/ply_cloud.h"
#include "fusion/tsdf_fusion.h"
#include "fusion/tsdf_surface.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

void check_settings(const FusionSettings& s) {
  const auto fail = [](const std::string& what) { throw InputError("fusion settings: " + what); };
  if (s.pixel_stride < 1) fail("pixel_stride must be at least 1");
  if (!(s.max_depth > 0)) fail("max_depth must be positive");
  if (!(s.voxel_size > 0)) fail("voxel_size must be positive");
  if (s.batch_frames < 1) fail("batch_frames must be at least 1");
  if (!(s.outlier_neighbour_share >= 0 && s.outlier_neighbour_share <= 1))
    fail("outlier_neighbour_share must be within 0..1");
  if (!(s.truncation >= s.voxel_size)) fail("truncation must be at least voxel_size");
  if (!(s.edge_jump >= 0)) fail("edge_jump must not be negative");
  if (!(s.min_weight >= 0)) fail("min_weight must not be negative");
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

// Each frame's images and buffers (0.3 to 1 MB each) are allocated and freed hundreds of times.
// glibc's defaults map the larger ones afresh and give the heap's free top back to the system,
// so every use faults its pages in again (a fifth of fusion's time, most of it in the kernel).
// Kept in the heap instead, for the rest of the process (fusion is a process's last stage).
void keep_frame_buffers_in_heap() {
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
  mallopt(M_TRIM_THRESHOLD, 32 << 20);
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
                      const fs::path& mesh_path,
                      const std::function<void(size_t, size_t)>& progress) {
  Stopwatch clock;
  check_settings(settings);
  for (const FusionFrame& f : frames)
    if (f.index >= sequence.size())
      throw_input_error(sequence.folder().string(),
                        "frame " + std::to_string(f.index) + " is out of range: the sequence has " +
                            std::to_string(sequence.size()) + " frames");
  const bool mesh = settings.mesh && settings.method == MapMethod::kTsdf && !mesh_path.empty();
  check_writable(ply_path);
  if (mesh) check_writable(mesh_path);

  keep_frame_buffers_in_heap();
  FusionReport report;
  report.method = settings.method;
  report.frames = frames.size();
  PlyCloud map = settings.method == MapMethod::kTsdf
                     ? fuse_tsdf(sequence, frames, settings, report, progress)
                     : fuse_centroids(sequence, frames, settings, report, progress);
  if (map.points.empty())
    throw_input_error(ply_path.string(),
                      "no point to write: no frame has valid depth within max_depth " +
                          std::to_string(settings.max_depth) + " m");
  std::vector<std::array<uint32_t, 3>> triangles = std::move(map.triangles);
  map.triangles.clear();
  write_ply_cloud(ply_path, map, settings.binary_ply);
  if (mesh) {
    map.triangles = std::move(triangles);
    write_ply_cloud(mesh_path, referenced_vertices(std::move(map)), settings.binary_ply);
  }
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
