#pragma once
// Statistics of a TUM-layout sequence that tell a synthetic sensor from a real one: depth noise
// against distance, invalid depth, sharpness against angular speed, and how many ORB matches
// between consecutive frames one motion explains. Measured on evenly spaced sampled frames.
#include <optional>
#include <vector>

#include "eval/sequence_stats/depth_noise.h"
#include "eval/sequence_stats/invalid_depth.h"
#include "eval/sequence_stats/match_inliers.h"
#include "io/tum_sequence.h"

namespace slamkit::stats {

struct SequenceStatsSettings {
  size_t sample = 30;  // frames, evenly spaced over the sequence; 0 = all
  DepthNoiseSettings noise;
  InvalidDepthSettings invalid;
  // Lower edges of the angular speed bins (deg/s); the last bin is open above.
  std::vector<double> speed_edges = {0, 10, 20, 40, 80, 160};
  MatchInlierSettings matching;
};

// One sampled frame; `pair` is its match with the next frame of the sequence (none for the
// last frame).
struct FrameRecord {
  size_t index = 0;
  double stamp = 0;
  double sharpness = 0;                 // laplacian_variance()
  std::optional<double> angular_speed;  // deg/s from groundtruth
  size_t planar_patches = 0;
  std::optional<PairInliers> pair;
};

struct SpeedBin {
  double low = 0, high = 0;  // deg/s; high is +inf for the last bin
  size_t frames = 0;
  double median_sharpness = 0;
};

struct InlierSummary {
  size_t pairs = 0;   // pairs tried
  size_t fitted = 0;  // pairs with a pose (the quantiles are over these)
  double q1 = 0, median = 0, q3 = 0;
  double median_matches = 0, median_correspondences = 0;
};

struct SequenceStats {
  size_t frames = 0;  // in the sequence
  std::vector<FrameRecord> sampled;
  size_t patches = 0;
  std::vector<DepthBin> noise_bins;
  std::optional<NoiseModel> noise_model;
  InvalidCounts invalid;
  double median_sharpness = 0;  // over all sampled frames, with groundtruth or not
  std::vector<SpeedBin> speed_bins;
  size_t frames_with_speed = 0;
  std::optional<double> sharpness_speed_correlation;  // Pearson, over frames with a speed
  InlierSummary inliers;
};

// Throws InputError (naming the file) for a frame that cannot be loaded.
SequenceStats compute_sequence_stats(const TumSequence& sequence,
                                     const SequenceStatsSettings& settings);

}  // namespace slamkit::stats
