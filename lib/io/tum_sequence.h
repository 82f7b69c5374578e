#pragma once
// A TUM RGB-D sequence folder: rgb/ depth/ rgb.txt depth.txt [groundtruth.txt].
// Opening parses and checks the lists and associates RGB with depth; images are decoded
// only when a frame is loaded.
#include <filesystem>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/trajectory.h"

namespace slamkit {

struct StampedFile {
  double stamp = 0;
  std::string file;  // relative to the sequence folder, as listed
  int line = 0;      // line in the list file, for error messages
};

struct FrameFiles {
  StampedFile rgb;
  StampedFile depth;
};

struct RgbdFrame {
  size_t index = 0;
  double stamp = 0;  // the RGB timestamp (the one trajectories carry)
  cv::Mat rgb;       // CV_8UC3, BGR as OpenCV decodes it
  cv::Mat depth;     // CV_32FC1, metres; 0 where invalid (0 in the file, or out of range)
};

struct SequenceOptions {
  double max_time_diff = 0.02;  // RGB-depth association tolerance, seconds (associate.py)
  double time_offset = 0.0;     // added to depth stamps before associating
  std::optional<std::filesystem::path> association_file;  // use this instead of associating
  std::optional<std::filesystem::path> calibration_file;  // YAML; overrides the preset
  std::optional<double> depth_scale;                      // overrides the camera's
};

// "timestamp filename" lists (rgb.txt, depth.txt). Throws InputError naming file and line.
std::vector<StampedFile> read_file_list(const std::filesystem::path& path);

class TumSequence {
 public:
  // The camera is the calibration file given, else the folder's calibration.yaml, else the
  // Freiburg preset its name says. Throws InputError for a missing folder or list, malformed
  // lines, no RGB-depth pair within tolerance, no camera, and a
  // groundtruth that does not overlap the frames.
  static TumSequence open(const std::filesystem::path& folder, const SequenceOptions& options = {});

  const std::filesystem::path& folder() const { return folder_; }
  const Camera& camera() const { return camera_; }
  size_t size() const { return frames_.size(); }
  const FrameFiles& files(size_t i) const { return frames_.at(i); }
  double stamp(size_t i) const { return frames_.at(i).rgb.stamp; }
  // When frame i's depth image was taken: its stamp in depth.txt (or the association file)
  // plus the options' time_offset, the depth clock's correction.
  double depth_stamp(size_t i) const { return frames_.at(i).depth.stamp + depth_time_offset_; }
  double duration() const {
    return frames_.empty() ? 0 : frames_.back().rgb.stamp - frames_.front().rgb.stamp;
  }
  const std::optional<Trajectory>& groundtruth() const { return groundtruth_; }

  // Decodes frame i. Throws InputError for a missing or unreadable PNG, a depth image that is
  // not 16-bit single channel, a colour image that is not 8-bit, or sizes that differ from
  // each other or from the camera's.
  RgbdFrame load(size_t i) const;

 private:
  std::filesystem::path folder_;
  Camera camera_;
  std::vector<FrameFiles> frames_;
  double depth_time_offset_ = 0;
  std::optional<Trajectory> groundtruth_;
};

}  // namespace slamkit
