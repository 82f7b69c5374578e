#pragma once
// When the kinect sensor's frames are taken: colour on the 30 Hz grid of the ideal sensor,
// depth on a clock of its own (an offset that drifts, plus jitter, as TUM fr1's lists show),
// the pairs TUM's associate.py would make, and the 100 Hz groundtruth stamps.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "datasets/synth/kinect_sensor.h"

namespace slamkit::synth {

// Stamps are integer microseconds from the first colour frame (0), as the lists print them.
struct StreamStamps {
  std::vector<int64_t> colour, depth, groundtruth;
  // (colour index, depth index) in colour order.
  std::vector<std::pair<int, int>> pairs;
};

// Depth frame k is at depth_offset_s + k * (1 + depth_drift) / 30 s plus jitter (seeded by
// `seed`), kept while within the colour frames' span; with stream_timing off depth shares the
// colour stamps. Groundtruth covers both streams at groundtruth_rate_hz (one per colour frame
// when stream_timing is off).
StreamStamps make_stream_stamps(const KinectSettings& settings, int frames, uint64_t seed);

// associate.py's pairing: every (colour, depth) within max_difference_s, taken greedily by the
// smallest difference, each stamp used once; returned in colour order.
std::vector<std::pair<int, int>> associate_stamps(const std::vector<int64_t>& colour,
                                                  const std::vector<int64_t>& depth,
                                                  double max_difference_s = 0.02);

// "1600000000.033333" for a stamp in microseconds from the first frame.
std::string stamp_text(int64_t microseconds);
double stamp_seconds(int64_t microseconds);

}  // namespace slamkit::synth
