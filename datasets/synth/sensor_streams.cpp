#include "datasets/synth/sensor_streams.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "datasets/synth/counter_rng.h"
#include "datasets/synth/trajectory_presets.h"

namespace slamkit::synth {
namespace {

constexpr int64_t kFirstStampMicroseconds = 1600000000LL * 1000000LL;

int64_t colour_stamp(int i) { return std::llround(i * 1e6 / kFrameRate); }

}  // namespace

std::string stamp_text(int64_t microseconds) {
  const int64_t us = kFirstStampMicroseconds + microseconds;
  char text[32];
  std::snprintf(text, sizeof text, "%" PRId64 ".%06" PRId64, us / 1000000, us % 1000000);
  return text;
}

double stamp_seconds(int64_t microseconds) {
  return double(kFirstStampMicroseconds + microseconds) / 1e6;
}

StreamStamps make_stream_stamps(const KinectSettings& settings, int frames, uint64_t seed) {
  StreamStamps s;
  for (int i = 0; i < frames; ++i) s.colour.push_back(colour_stamp(i));
  if (!settings.has(KinectEffect::kStreamTiming)) {
    s.depth = s.groundtruth = s.colour;
    for (int i = 0; i < frames; ++i) s.pairs.emplace_back(i, i);
    return s;
  }
  // The depth clock starts depth_offset_s from the colour one and runs at its own rate; a
  // frame is kept while it lies within half a period of the colour frames, as a recording of
  // both streams would hold.
  const double period_us = 1e6 / kFrameRate * (1 + settings.depth_drift);
  const double half_period_us = 0.5e6 / kFrameRate;
  for (int k = 0;; ++k) {
    CounterRng rng(seed, kStreamDepthStamps, uint64_t(k));
    const double us = settings.depth_offset_s * 1e6 + k * period_us +
                      settings.depth_jitter_s * 1e6 * rng.approx_gaussian8();
    if (us > s.colour.back() + half_period_us) break;
    if (us < -half_period_us) continue;
    const int64_t stamp = std::llround(us);
    // Jitter never reorders the stream (a later frame is read later).
    if (!s.depth.empty() && stamp <= s.depth.back()) continue;
    s.depth.push_back(stamp);
  }
  const int64_t first = std::min(s.colour.front(), s.depth.front());
  const int64_t last = std::max(s.colour.back(), s.depth.back());
  const double step_us = 1e6 / settings.groundtruth_rate_hz;
  for (int k = 0; first + k * step_us <= last + step_us; ++k)
    s.groundtruth.push_back(first + std::llround(k * step_us));
  s.pairs = associate_stamps(s.colour, s.depth);
  return s;
}

std::vector<std::pair<int, int>> associate_stamps(const std::vector<int64_t>& colour,
                                                  const std::vector<int64_t>& depth,
                                                  double max_difference_s) {
  const int64_t max_us = std::llround(max_difference_s * 1e6);
  std::vector<std::tuple<int64_t, int, int>> candidates;  // |difference|, colour, depth
  for (int i = 0; i < int(colour.size()); ++i) {
    // Both lists are sorted: only depth stamps near colour[i] can be within the tolerance.
    auto it = std::lower_bound(depth.begin(), depth.end(), colour[i] - max_us);
    for (; it != depth.end() && *it < colour[i] + max_us; ++it)
      candidates.emplace_back(std::llabs(*it - colour[i]), i, int(it - depth.begin()));
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> colour_used(colour.size()), depth_used(depth.size());
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [difference, c, d] : candidates) {
    if (colour_used[c] || depth_used[d]) continue;
    colour_used[c] = depth_used[d] = true;
    pairs.emplace_back(c, d);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace slamkit::synth
