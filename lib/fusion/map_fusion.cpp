#include "fusion/map_fusion.h"

#include <omp.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/stopwatch.h"
#include "fusion/outlier_removal.h"
#include "fusion/ply_cloud.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZRGB>;

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

// Appends the frame's valid samples, in world coordinates, to `cloud`; returns how many.
size_t back_project(const FusionSamples& frame, const PixelGrid& grid,
                    const Eigen::Isometry3d& T_w_c, double max_depth, Cloud& cloud) {
  const Eigen::Matrix3d R = T_w_c.linear();
  const Eigen::Vector3d t = T_w_c.translation();
  const size_t before = cloud.size();
  for (size_t i = 0; i < grid.rays.size(); ++i) {
    const double z = frame.depth[i];
    if (!(z > 0 && z <= max_depth)) continue;
    const Eigen::Vector3d p_c(grid.rays[i].x() * z, grid.rays[i].y() * z, z);
    const cv::Vec3b& bgr = frame.bgr[i];
    pcl::PointXYZRGB p;
    p.getVector3fMap() = (R * p_c + t).cast<float>();
    p.r = bgr[2];
    p.g = bgr[1];
    p.b = bgr[0];
    cloud.push_back(p);
  }
  return cloud.size() - before;
}

// pcl::VoxelGrid, except that it never hits PCL's integer-overflow guard (which returns the
// input unfiltered when the grid has more than INT_MAX cells: about 13 m cubed at 1 cm): a
// cloud that large is split at a voxel boundary along its longest side and each half
// filtered. Voxels are aligned to multiples of the leaf in PCL, so the split changes nothing.
Cloud::Ptr voxel_grid(const Cloud::ConstPtr& in, float leaf) {
  auto out = std::make_shared<Cloud>();
  if (in->empty()) return out;
  Eigen::Array3f lo = in->front().getArray3fMap(), hi = lo;
  for (const pcl::PointXYZRGB& p : *in) {
    lo = lo.min(p.getArray3fMap());
    hi = hi.max(p.getArray3fMap());
  }
  const float inverse = 1.0f / leaf;  // as PCL computes it
  const Eigen::Array3d cells = ((hi - lo) * inverse).cast<double>() + 2.0;
  if (cells.prod() < INT_MAX / 2) {
    pcl::VoxelGrid<pcl::PointXYZRGB> filter;
    filter.setLeafSize(leaf, leaf, leaf);
    filter.setInputCloud(in);
    filter.filter(*out);
    return out;
  }
  int axis = 0;
  cells.maxCoeff(&axis);
  const float split = std::floor(0.5f * (lo[axis] + hi[axis]) * inverse);
  auto low = std::make_shared<Cloud>(), high = std::make_shared<Cloud>();
  for (const pcl::PointXYZRGB& p : *in)
    (std::floor(p.getArray3fMap()[axis] * inverse) < split ? low : high)->push_back(p);
  *out = *voxel_grid(low, leaf);
  *out += *voxel_grid(high, leaf);
  return out;
}

void check_settings(const FusionSettings& s) {
  const auto fail = [](const std::string& what) { throw InputError("fusion settings: " + what); };
  if (s.pixel_stride < 1) fail("pixel_stride must be at least 1");
  if (!(s.max_depth > 0)) fail("max_depth must be positive");
  if (!(s.voxel_size > 0)) fail("voxel_size must be positive");
  if (s.batch_frames < 1) fail("batch_frames must be at least 1");
  if (s.remove_outliers && s.outlier_neighbours < 1) fail("outlier_neighbours must be >= 1");
  if (s.remove_outliers && !(s.outlier_std_ratio > 0)) fail("outlier_std_ratio must be > 0");
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

// Points held at once, over all threads; the report's peak_points.
class PointCount {
 public:
  void add(size_t n) {
    const size_t now = held_ += n;
    size_t peak = peak_.load();
    while (now > peak && !peak_.compare_exchange_weak(peak, now)) {
    }
  }
  void remove(size_t n) { held_ -= n; }
  size_t peak() const { return peak_; }

 private:
  std::atomic<size_t> held_{0}, peak_{0};
};

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

FusionReport fuse_map(const TumSequence& sequence, const std::vector<FusionFrame>& frames,
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
  const float leaf = float(settings.voxel_size);
  const size_t batch_size = size_t(settings.batch_frames);
  const size_t batches = (frames.size() + batch_size - 1) / batch_size;
  // Re-voxelising the merged cloud when it has doubled keeps it under about twice the map's
  // voxel count at an amortised cost of one pass per doubling.
  const size_t batch_capacity = batch_size * grid.rays.size();
  size_t revoxelise_at = 2 * batch_capacity;

  FusionReport report;
  report.frames = frames.size();
  PointCount held;
  auto merged = std::make_shared<Cloud>();
  // Batches after a failing one are skipped; those before it all run, so the error reported
  // is the earliest failing frame's whatever the threads did.
  std::atomic<long> first_failed{LONG_MAX};
  std::string error;
  size_t raw_points = 0, done = 0;

  // Batches run in parallel, each on one thread (load, back-project, voxelise); the ordered
  // section merges them in frame order, so the result does not depend on the thread count.
  // Each thread keeps its raw cloud's memory from batch to batch: allocated afresh, its pages
  // (39 MB a batch at the defaults) were faulted in again every time.
#pragma omp parallel
  {
    auto raw = std::make_shared<Cloud>();
#pragma omp for ordered schedule(dynamic, 1)
    for (long b = 0; b < long(batches); ++b) {
      const size_t first = size_t(b) * batch_size,
                   last = std::min(first + batch_size, frames.size());
      Cloud::Ptr voxels;
      std::string batch_error;
      size_t batch_raw = 0;
      if (b < first_failed) {
        try {  // exceptions must not escape an OpenMP region
          raw->clear();
          const size_t capacity = raw->points.capacity();
          raw->reserve((last - first) * grid.rays.size());
          held.add(raw->points.capacity() - capacity);
          for (size_t i = first; i < last; ++i) {
            const FusionFrame& f = frames[i];
            if (f.samples) {
              batch_raw += back_project(*f.samples, grid, f.T_w_c, settings.max_depth, *raw);
            } else {
              const RgbdFrame frame = sequence.load(f.index);
              batch_raw +=
                  back_project(sample_for_fusion(frame.rgb, frame.depth, settings.pixel_stride),
                               grid, f.T_w_c, settings.max_depth, *raw);
            }
          }
          voxels = voxel_grid(raw, leaf);
          held.add(voxels->size());
        } catch (const std::exception& e) {
          batch_error = e.what();
          long expected = first_failed;
          while (b < expected && !first_failed.compare_exchange_weak(expected, b)) {
          }
        }
      }
#pragma omp ordered
      {
        if (error.empty()) error = batch_error;
        if (error.empty() && voxels) {
          *merged += *voxels;  // the batch's points move into the merged cloud
          voxels.reset();
          raw_points += batch_raw;
          done = last;
          if (merged->size() > revoxelise_at) {
            Cloud::Ptr smaller = voxel_grid(merged, leaf);
            held.add(smaller->size());
            held.remove(merged->size());
            merged = smaller;
            revoxelise_at = std::max(2 * merged->size(), 2 * batch_capacity);
          }
          if (progress && omp_get_thread_num() == 0) progress(done, frames.size());
        }
      }
    }
    held.remove(raw->points.capacity());
  }
  if (!error.empty()) throw InputError(error);
  if (progress) progress(done, frames.size());
  report.raw_points = raw_points;

  Cloud::Ptr map = voxel_grid(merged, leaf);
  held.add(map->size());
  report.after_voxel_grid = map->size();
  merged.reset();
  if (settings.remove_outliers && !map->empty()) {
    std::vector<Eigen::Vector3f> positions;
    positions.reserve(map->size());
    for (const pcl::PointXYZRGB& p : *map) positions.push_back(p.getVector3fMap());
    auto inliers = std::make_shared<Cloud>();
    for (size_t i : statistical_inliers(positions, settings.outlier_neighbours,
                                        settings.outlier_std_ratio))
      inliers->push_back((*map)[i]);
    held.add(inliers->size());
    map = inliers;
  }
  report.after_outlier_removal = map->size();
  report.peak_points = held.peak();
  if (map->empty())
    throw_input_error(ply_path.string(),
                      "no point to write: no frame has valid depth within max_depth " +
                          std::to_string(settings.max_depth) + " m");

  PlyCloud out;
  out.points.reserve(map->size());
  out.colours.reserve(map->size());
  for (const pcl::PointXYZRGB& p : *map) {
    out.points.push_back(p.getVector3fMap());
    out.colours.push_back({p.r, p.g, p.b});
  }
  map.reset();
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
