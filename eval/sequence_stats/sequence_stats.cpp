#include "eval/sequence_stats/sequence_stats.h"

#include <limits>

#include "core/progress.h"
#include "eval/sequence_stats/angular_speed.h"
#include "eval/sequence_stats/distribution.h"
#include "eval/sequence_stats/sharpness.h"
#include "features/orb_extractor.h"

namespace slamkit::stats {
namespace {

std::vector<size_t> sampled_indices(size_t frames, size_t sample) {
  const size_t count = sample == 0 ? frames : std::min(sample, frames);
  std::vector<size_t> indices;
  for (size_t k = 0; k < count; ++k)
    indices.push_back(count == 1 ? 0 : k * (frames - 1) / (count - 1));
  return indices;
}

std::vector<SpeedBin> speed_bins(const std::vector<FrameRecord>& frames,
                                 const std::vector<double>& edges) {
  std::vector<SpeedBin> bins;
  for (size_t k = 0; k < edges.size(); ++k) {
    SpeedBin bin;
    bin.low = edges[k];
    bin.high = k + 1 < edges.size() ? edges[k + 1] : std::numeric_limits<double>::infinity();
    std::vector<double> sharpness;
    for (const FrameRecord& f : frames)
      if (f.angular_speed && *f.angular_speed >= bin.low && *f.angular_speed < bin.high)
        sharpness.push_back(f.sharpness);
    bin.frames = sharpness.size();
    bin.median_sharpness = median(sharpness);
    bins.push_back(bin);
  }
  return bins;
}

InlierSummary summarise_inliers(const std::vector<FrameRecord>& frames) {
  InlierSummary s;
  std::vector<double> shares, matches, correspondences;
  for (const FrameRecord& f : frames) {
    if (!f.pair) continue;
    ++s.pairs;
    matches.push_back(double(f.pair->matches));
    correspondences.push_back(double(f.pair->correspondences));
    if (f.pair->fitted) shares.push_back(f.pair->share());
  }
  s.fitted = shares.size();
  s.q1 = quantile(shares, 0.25);
  s.median = quantile(shares, 0.5);
  s.q3 = quantile(shares, 0.75);
  s.median_matches = median(matches);
  s.median_correspondences = median(correspondences);
  return s;
}

}  // namespace

SequenceStats compute_sequence_stats(const TumSequence& sequence,
                                     const SequenceStatsSettings& settings) {
  const Camera& camera = sequence.camera();
  const cv::Mat rays = pixel_rays(camera);
  SequenceStats stats;
  stats.frames = sequence.size();
  std::vector<PatchNoise> patches;

  // The next frame's features are kept: with every frame sampled, frame i+1 is the next sample.
  std::optional<size_t> kept_index;
  FrameFeatures kept;
  const auto features_of = [&](size_t i, const RgbdFrame& frame) {
    if (kept_index != i) kept = extract_orb(frame.rgb, camera, settings.matching.orb);
    kept_index = i;
    return kept;
  };

  const std::vector<size_t> indices = sampled_indices(sequence.size(), settings.sample);
  Progress progress("stats", indices.size());
  for (size_t k = 0; k < indices.size(); ++k) {
    const size_t i = indices[k];
    const RgbdFrame frame = sequence.load(i);
    FrameRecord record;
    record.index = i;
    record.stamp = frame.stamp;
    record.sharpness = laplacian_variance(frame.rgb);
    if (sequence.groundtruth())
      record.angular_speed = angular_speed_deg(*sequence.groundtruth(), frame.stamp);
    const std::vector<PatchNoise> found = patch_noise(frame.depth, rays, settings.noise);
    record.planar_patches = found.size();
    patches.insert(patches.end(), found.begin(), found.end());
    stats.invalid += count_invalid(frame.depth, settings.invalid);
    if (i + 1 < sequence.size()) {
      const FrameFeatures a = features_of(i, frame);
      const RgbdFrame next = sequence.load(i + 1);
      record.pair =
          match_inliers(a, frame.depth, features_of(i + 1, next), camera, settings.matching);
    }
    stats.sampled.push_back(record);
    progress.update(k + 1);
  }

  stats.patches = patches.size();
  stats.noise_bins = bin_noise(patches, settings.noise);
  stats.noise_model = fit_noise_model(stats.noise_bins, settings.noise);
  std::vector<double> all_sharpness, speeds, sharpness;
  for (const FrameRecord& f : stats.sampled) {
    all_sharpness.push_back(f.sharpness);
    if (!f.angular_speed) continue;
    speeds.push_back(*f.angular_speed);
    sharpness.push_back(f.sharpness);
  }
  stats.median_sharpness = median(all_sharpness);
  stats.frames_with_speed = speeds.size();
  stats.speed_bins = speed_bins(stats.sampled, settings.speed_edges);
  stats.sharpness_speed_correlation = pearson(speeds, sharpness);
  stats.inliers = summarise_inliers(stats.sampled);
  return stats;
}

}  // namespace slamkit::stats
