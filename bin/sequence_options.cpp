#include "bin/sequence_options.h"

#include <string>
#include <vector>

#include "settings/settings_fields.h"

namespace slamkit::cli {

void add_sequence_options(CLI::App* command, SequenceOptions& options) {
  command->add_option_function<std::string>(
      "--calibration", [&options](const std::string& f) { options.calibration_file = f; },
      "Camera calibration YAML (default: the Freiburg preset named by the folder)");
  command->add_option_function<std::string>(
      "--association", [&options](const std::string& f) { options.association_file = f; },
      "Use this 'rgb_time rgb_file depth_time depth_file' file instead of associating");
  command->add_option_function<double>(
      "--depth-scale", [&options](double s) { options.depth_scale = s; },
      "Raw depth units per metre (default 5000; ORB-SLAM2 uses 5208 for Freiburg 2)");
  command->add_option("--max-diff", options.max_time_diff,
                      "RGB-depth association tolerance in seconds")
      ->capture_default_str();
  command->add_option("--offset", options.time_offset, "Time offset added to depth stamps (s)")
      ->capture_default_str();
}

void add_lost_frames_option(CLI::App* command, std::optional<LostFrames>& lost_frames) {
  std::vector<std::string> names;
  for (const auto& entry : kLostFramesNames) names.push_back(entry.name);
  command
      ->add_option_function<std::string>(
          "--lost-frames",
          [&lost_frames](const std::string& name) {
            lost_frames = value_named(kLostFramesNames, name);
          },
          "Frames whose tracking failed: 'omit' them from the trajectory files (default, as "
          "ORB-SLAM2) or write the motion model's pose")
      ->check(CLI::IsMember(names));
}

}  // namespace slamkit::cli
