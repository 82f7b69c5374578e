#include "loop/training_descriptors.h"

#include <exception>

#include "features/orb_extractor.h"

namespace slamkit {

std::vector<cv::Mat> sequence_descriptors(const TumSequence& sequence, const OrbSettings& orb,
                                          int frame_step) {
  const size_t step = size_t(std::max(frame_step, 1));
  std::vector<cv::Mat> images((sequence.size() + step - 1) / step);
  std::vector<std::exception_ptr> errors(images.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < long(images.size()); ++k) {
    try {
      const RgbdFrame frame = sequence.load(size_t(k) * step);
      images[size_t(k)] = extract_orb(frame.rgb, sequence.camera(), orb).descriptors;
    } catch (...) {
      errors[size_t(k)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
  return images;
}

}  // namespace slamkit
