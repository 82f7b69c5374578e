#include "pipeline/frame_preparation.h"

#include <exception>

#include "core/stopwatch.h"
#include "features/orb_extractor.h"

namespace slamkit {

std::vector<PreparedFrame> prepare_frames(const TumSequence& sequence, size_t begin, size_t end,
                                          const Settings& settings, const WindowPattern& pattern) {
  std::vector<PreparedFrame> frames(end - begin);
  std::vector<std::exception_ptr> errors(frames.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < long(frames.size()); ++k) {
    try {
      PreparedFrame& out = frames[size_t(k)];
      Stopwatch watch;
      const RgbdFrame frame = sequence.load(begin + size_t(k));
      out.decode_ms = watch.lap();
      out.index = frame.index;
      out.stamp = frame.stamp;
      out.depth_stamp = sequence.depth_stamp(begin + size_t(k));
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
      errors[size_t(k)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return frames;
}

}  // namespace slamkit
