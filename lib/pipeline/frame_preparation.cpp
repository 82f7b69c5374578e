#include "pipeline/frame_preparation.h"

#include <omp.h>

#include <atomic>
#include <exception>
#include <thread>

#include "core/stopwatch.h"
#include "features/orb_extractor.h"

namespace slamkit {

std::vector<PreparedFrame> prepare_frames(const TumSequence& sequence, size_t begin, size_t end,
                                          const Settings& settings, const WindowPattern& pattern) {
  std::vector<PreparedFrame> frames(end - begin);
  std::vector<std::exception_ptr> errors(frames.size());
  const auto prepare = [&](size_t k) {
    try {
      PreparedFrame& out = frames[k];
      Stopwatch watch;
      const RgbdFrame frame = sequence.load(begin + k);
      out.decode_ms = watch.lap();
      out.index = frame.index;
      out.stamp = frame.stamp;
      out.depth_stamp = sequence.depth_stamp(begin + k);
      out.depth = frame.depth;
      out.rgb = frame.rgb;
      out.features = extract_orb(frame.rgb, sequence.camera(), settings.orb);
      out.keypoint_depths = keypoint_depths(out.features, frame.depth);
      out.features_ms = watch.lap();
      // The window code reads the feature pyramid (it codes each pyramid level:
      // docs/method.md#keyframes), unless the keyframe settings ask for other levels than ORB's.
      const ImagePyramid& grey = out.features.pyramid;
      out.window_code =
          fits(grey, pattern)
              ? encode_windows(grey, pattern)
              : encode_windows(build_pyramid(grey.levels[0], settings.keyframes.pyramid_levels,
                                             settings.keyframes.scale_factor),
                               pattern);
      out.window_code_ms = watch.lap();
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  // Frames go to `--threads` threads (OpenMP's setting) through a counter, not an OpenMP loop:
  // libgomp's idle threads spin (by default 300,000 pause instructions before they sleep) at
  // the end of each chunk, on the cores the tracking and local BA threads need (desk 600: 2 %
  // more CPU).
  std::atomic<size_t> next{0};
  const auto work = [&] {
    for (size_t k = next++; k < frames.size(); k = next++) prepare(k);
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < omp_get_max_threads(); ++t) helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers) helper.join();
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return frames;
}

}  // namespace slamkit
