#include "io/tum_sequence.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/association.h"
#include "core/error.h"
#include "io/camera_yaml.h"
#include "io/path_kind.h"
#include "io/png_file.h"
#include "io/text_table.h"
#include "io/trajectory_io.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

StampedFile stamped_file(const fs::path& list, const TableRow& row, size_t field) {
  const double stamp = parse_number(list, row, field);
  if (!std::isfinite(stamp)) throw_input_error(list.string(), row.line, "timestamp is not finite");
  return {stamp, row.fields.at(field + 1), row.line};
}

void sort_by_stamp(std::vector<StampedFile>& files) {
  std::stable_sort(files.begin(), files.end(),
                   [](const StampedFile& a, const StampedFile& b) { return a.stamp < b.stamp; });
}

std::vector<FrameFiles> read_association_file(const fs::path& path) {
  std::vector<FrameFiles> frames;
  for (const TableRow& row : read_table(path)) {
    if (row.fields.size() < 4)
      throw_input_error(path.string(), row.line,
                        "expected 'rgb_time rgb_file depth_time depth_file', found " +
                            std::to_string(row.fields.size()) + " fields");
    frames.push_back({stamped_file(path, row, 0), stamped_file(path, row, 2)});
  }
  if (frames.empty()) throw_input_error(path.string(), "no frame listed");
  std::stable_sort(frames.begin(), frames.end(), [](const FrameFiles& a, const FrameFiles& b) {
    return a.rgb.stamp < b.rgb.stamp;
  });
  return frames;
}

std::vector<FrameFiles> associate_lists(const fs::path& folder, const SequenceOptions& options) {
  std::vector<StampedFile> rgb = read_file_list(folder / "rgb.txt");
  std::vector<StampedFile> depth = read_file_list(folder / "depth.txt");
  sort_by_stamp(rgb);
  sort_by_stamp(depth);
  std::vector<double> rgb_stamps, depth_stamps;
  for (const auto& f : rgb) rgb_stamps.push_back(f.stamp);
  for (const auto& f : depth) depth_stamps.push_back(f.stamp);
  if (too_crowded_to_associate(rgb_stamps, depth_stamps, options.max_time_diff,
                               options.time_offset))
    throw_input_error((folder / "rgb.txt").string(),
                      "timestamps too crowded to associate: over " +
                          std::to_string(kMaxCandidatesPerStamp) +
                          " depth stamps within the tolerance of each RGB stamp on average "
                          "(repeated stamps, or stamps not in seconds?)");
  std::vector<FrameFiles> frames;
  for (const IndexPair& m :
       associate_greedy(rgb_stamps, depth_stamps, options.max_time_diff, options.time_offset))
    frames.push_back({rgb[m.first], depth[m.second]});
  if (frames.empty())
    throw_input_error((folder / "rgb.txt").string(),
                      "no RGB frame has a depth frame within " +
                          std::to_string(options.max_time_diff) + " s (depth.txt has " +
                          std::to_string(depth.size()) + " entries)");
  return frames;
}

Camera choose_camera(const fs::path& folder, const SequenceOptions& options) {
  // Precedence: the file the user names, then the folder's own calibration.yaml (synthetic
  // sequences carry one), then the Freiburg preset named by the folder.
  Camera camera;
  const fs::path folder_calibration = folder / "calibration.yaml";
  if (options.calibration_file) {
    camera = read_camera_yaml(*options.calibration_file);
  } else if (path_kind(folder_calibration) != PathKind::kMissing) {
    camera = read_camera_yaml(folder_calibration);
  } else if (auto preset = Camera::preset_for_sequence(folder)) {
    camera = *preset;
  } else {
    throw_input_error(folder.string(),
                      "cannot tell the camera: the folder name has no 'freiburg1/2/3' and it "
                      "holds no calibration.yaml; give a calibration file");
  }
  if (options.depth_scale) camera.depth_scale = *options.depth_scale;
  return camera;
}

std::string describe_type(const cv::Mat& m) {
  const int depth = m.depth();
  const char* bits = depth == CV_8U ? "8-bit" : depth == CV_16U ? "16-bit" : "non-integer";
  return std::string(bits) + " " + std::to_string(m.channels()) + "-channel";
}

cv::Mat read_listed_png(const fs::path& folder, const fs::path& list, const StampedFile& f) {
  const fs::path path = folder / f.file;
  if (path_kind(path) == PathKind::kMissing)
    throw_input_error(list.string(), f.line, "listed image does not exist: " + path.string());
  return read_png(path);
}

}  // namespace

std::vector<StampedFile> read_file_list(const fs::path& path) {
  std::vector<StampedFile> files;
  for (const TableRow& row : read_table(path)) {
    if (row.fields.size() < 2)
      throw_input_error(path.string(), row.line,
                        "expected 'timestamp filename', found " +
                            std::to_string(row.fields.size()) + " field(s)");
    files.push_back(stamped_file(path, row, 0));
  }
  if (files.empty()) throw_input_error(path.string(), "no image listed");
  return files;
}

TumSequence TumSequence::open(const fs::path& folder, const SequenceOptions& options) {
  const PathKind kind = path_kind(folder);
  if (kind == PathKind::kMissing) throw_input_error(folder.string(), "sequence folder not found");
  if (kind != PathKind::kFolder) throw_input_error(folder.string(), "not a folder");
  TumSequence seq;
  seq.folder_ = folder;
  seq.camera_ = choose_camera(folder, options);
  seq.depth_time_offset_ = options.time_offset;
  seq.frames_ = options.association_file ? read_association_file(*options.association_file)
                                         : associate_lists(folder, options);

  const fs::path gt_path = folder / "groundtruth.txt";
  if (path_kind(gt_path) != PathKind::kMissing) {
    TrajectoryFile gt = read_tum_trajectory(gt_path);
    size_t covered = 0;
    for (const FrameFiles& f : seq.frames_)
      if (gt.trajectory.nearest(f.rgb.stamp, options.max_time_diff)) ++covered;
    if (covered == 0) {
      char message[256];
      std::snprintf(message, sizeof message,
                    "groundtruth covers %.3f..%.3f s but the %zu frames span %.3f..%.3f s: "
                    "no frame has a pose within %.3f s",
                    gt.trajectory.start_time(), gt.trajectory.end_time(), seq.frames_.size(),
                    seq.frames_.front().rgb.stamp, seq.frames_.back().rgb.stamp,
                    options.max_time_diff);
      throw_input_error(gt_path.string(), message);
    }
    seq.groundtruth_ = std::move(gt.trajectory);
  }
  return seq;
}

RgbdFrame TumSequence::load(size_t i) const {
  const FrameFiles& files = frames_.at(i);
  const fs::path rgb_list = folder_ / "rgb.txt", depth_list = folder_ / "depth.txt";
  cv::Mat rgb = read_listed_png(folder_, rgb_list, files.rgb);
  cv::Mat raw_depth = read_listed_png(folder_, depth_list, files.depth);
  const std::string rgb_path = (folder_ / files.rgb.file).string();
  const std::string depth_path = (folder_ / files.depth.file).string();

  if (rgb.depth() != CV_8U)
    throw_input_error(rgb_path, "colour image must be 8-bit, found " + describe_type(rgb));
  if (rgb.channels() == 1) cv::cvtColor(rgb, rgb, cv::COLOR_GRAY2BGR);
  if (rgb.channels() == 4) cv::cvtColor(rgb, rgb, cv::COLOR_BGRA2BGR);
  if (raw_depth.type() != CV_16UC1)
    throw_input_error(
        depth_path, "depth image must be 16-bit single channel, found " + describe_type(raw_depth));
  if (rgb.size() != raw_depth.size())
    throw_input_error(depth_path, "depth is " + std::to_string(raw_depth.cols) + "x" +
                                      std::to_string(raw_depth.rows) + " but colour is " +
                                      std::to_string(rgb.cols) + "x" + std::to_string(rgb.rows));
  if (rgb.cols != camera_.width || rgb.rows != camera_.height)
    throw_input_error(rgb_path, "image is " + std::to_string(rgb.cols) + "x" +
                                    std::to_string(rgb.rows) + " but the camera is " +
                                    std::to_string(camera_.width) + "x" +
                                    std::to_string(camera_.height));

  RgbdFrame frame;
  frame.index = i;
  frame.stamp = files.rgb.stamp;
  frame.rgb = rgb;
  raw_depth.convertTo(frame.depth, CV_32F, 1.0 / camera_.depth_scale);
  // Out-of-range depth becomes 0 (invalid), as the file's own 0 is.
  cv::Mat invalid = (frame.depth < camera_.min_depth) | (frame.depth > camera_.max_depth);
  frame.depth.setTo(0.0f, invalid);
  return frame;
}

}  // namespace slamkit
