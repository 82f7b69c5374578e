#include "fusion/fusion_frames.h"

#include <string>

#include "core/error.h"

namespace slamkit {

void for_frames_in_parallel(const TumSequence& sequence, const std::vector<FusionFrame>& frames,
                            size_t first, size_t count, int pixel_stride,
                            const std::function<void(size_t, const FusionSamples&)>& work) {
  std::vector<std::string> errors(count);
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < long(count); ++k) {
    const size_t i = first + size_t(k);
    const FusionFrame& f = frames[i];
    try {  // exceptions must not escape an OpenMP region
      if (f.samples) {
        work(i, *f.samples);
      } else {
        const RgbdFrame frame = sequence.load(f.index);
        work(i, sample_for_fusion(frame.rgb, frame.depth, pixel_stride));
      }
    } catch (const std::exception& e) {
      errors[size_t(k)] = e.what();
    }
  }
  for (const std::string& error : errors)
    if (!error.empty()) throw InputError(error);
}

}  // namespace slamkit
