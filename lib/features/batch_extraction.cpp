#include "features/batch_extraction.h"

#include <omp.h>

#include <exception>

#include "features/orb_extractor.h"

namespace slamkit {

std::vector<FrameFeatures> extract_orb_batch(const std::vector<cv::Mat>& images,
                                             const Camera& camera, const OrbSettings& settings,
                                             int num_threads) {
  std::vector<FrameFeatures> results(images.size());
  // An exception may not leave an OpenMP region: keep one per frame, rethrow the first after.
  std::vector<std::exception_ptr> errors(images.size());
  const int threads = num_threads > 0 ? num_threads : omp_get_max_threads();
  const long count = static_cast<long>(images.size());
  // Frames cost differently (texture), hence dynamic scheduling; each writes its own slot.
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (long i = 0; i < count; ++i) {
    try {
      results[i] = extract_orb(images[i], camera, settings);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return results;
}

}  // namespace slamkit
