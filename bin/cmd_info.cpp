// slamkit info SEQ: what a sequence holds, before spending time on it; with --stats, how its
// sensor behaves (eval/sequence_stats), to compare synthetic sequences with real ones.
#include <cstdio>
#include <memory>
#include <optional>

#include <opencv2/core.hpp>

#include "bin/command.h"
#include "bin/sequence_options.h"
#include "core/progress.h"
#include "eval/sequence_stats/sequence_stats.h"
#include "eval/sequence_stats/stats_json.h"
#include "eval/sequence_stats/stats_text.h"
#include "io/atomic_file.h"
#include "io/tum_sequence.h"

namespace slamkit::cli {
namespace {

struct InfoArgs {
  std::string folder;
  SequenceOptions sequence;
  size_t sample = 30;
  bool stats = false;
  std::optional<std::filesystem::path> json;
};

void print_stats(const TumSequence& seq, const InfoArgs& args) {
  stats::SequenceStatsSettings settings;
  settings.sample = args.sample;
  const stats::SequenceStats result = stats::compute_sequence_stats(seq, settings);
  stats::print_stats(result, stdout);
  if (args.json)
    write_file_atomically(*args.json, [&](std::ostream& out) {
      out << stats::stats_json(result, seq.folder().string()).dump(2) << "\n";
    });
}

void print_info(const InfoArgs& args) {
  const TumSequence seq = TumSequence::open(args.folder, args.sequence);
  const Camera& cam = seq.camera();
  std::printf("sequence    %s\n", seq.folder().string().c_str());
  std::printf("frames      %zu associated RGB-D pairs\n", seq.size());
  std::printf("duration    %.3f s (%.6f .. %.6f), %.1f Hz\n", seq.duration(), seq.stamp(0),
              seq.stamp(seq.size() - 1),
              seq.size() > 1 ? (seq.size() - 1) / seq.duration() : 0.0);
  std::printf("camera      %s  fx %.1f fy %.1f cx %.1f cy %.1f  %dx%d\n", cam.name.c_str(),
              cam.fx, cam.fy, cam.cx, cam.cy, cam.width, cam.height);
  std::printf("distortion  %s (k1 %.4f k2 %.4f p1 %.4f p2 %.4f k3 %.4f)\n",
              cam.distortion.is_zero() ? "none" : "radial-tangential", cam.distortion.k1,
              cam.distortion.k2, cam.distortion.p1, cam.distortion.p2, cam.distortion.k3);
  std::printf("depth       %.0f units/m, valid %.2f..%.2f m\n", cam.depth_scale, cam.min_depth,
              cam.max_depth);

  // Depth validity over evenly spaced frames (all of them when the sequence is short).
  const size_t count = args.sample == 0 ? seq.size() : std::min(args.sample, seq.size());
  double valid_sum = 0, depth_sum = 0;
  size_t depth_pixels = 0;
  Progress progress("info", count);
  for (size_t k = 0; k < count; ++k) {
    const size_t i = count == 1 ? 0 : k * (seq.size() - 1) / (count - 1);
    const RgbdFrame frame = seq.load(i);
    const cv::Mat valid = frame.depth > 0;
    const int n = cv::countNonZero(valid);
    valid_sum += double(n) / frame.depth.total();
    depth_sum += cv::sum(frame.depth)[0];
    depth_pixels += n;
    progress.update(k + 1);
  }
  std::printf("depth data  %.1f%% of pixels valid, mean %.2f m (over %zu of %zu frames)\n",
              100.0 * valid_sum / count, depth_pixels ? depth_sum / depth_pixels : 0.0, count,
              seq.size());

  if (!seq.groundtruth()) {
    std::printf("groundtruth none\n");
  } else {
    const Trajectory& gt = *seq.groundtruth();
    size_t covered = 0;
    for (size_t i = 0; i < seq.size(); ++i)
      if (gt.nearest(seq.stamp(i), args.sequence.max_time_diff)) ++covered;
    std::printf("groundtruth %zu poses, %.6f .. %.6f; %zu of %zu frames (%.1f%%) have a pose "
                "within %.3f s\n",
                gt.size(), gt.start_time(), gt.end_time(), covered, seq.size(),
                100.0 * covered / seq.size(), args.sequence.max_time_diff);
  }
  if (args.stats) print_stats(seq, args);
}

const bool kRegistered = register_command([](CLI::App& root) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = root.add_subcommand("info", "Summarise a TUM RGB-D sequence folder");
  cmd->add_option("sequence", args->folder, "Sequence folder (TUM layout)")->required();
  cmd->add_option("--sample", args->sample,
                  "Frames decoded to measure depth validity and the statistics (0 = all)")
      ->capture_default_str();
  CLI::Option* stats_flag = cmd->add_flag(
      "--stats", args->stats,
      "Also measure depth noise, invalid depth, sharpness and ORB match inliers");
  cmd->add_option("--json", args->json, "Write the statistics to this JSON file")
      ->needs(stats_flag);
  add_sequence_options(cmd, args->sequence);
  cmd->callback([args] { print_info(*args); });
});

}  // namespace
}  // namespace slamkit::cli
