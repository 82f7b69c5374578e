#include "fusion/keyframe_samples.h"

namespace slamkit {

KeyframeSamples::KeyframeSamples(const FusionSettings& settings)
    : keep_(settings.enabled && settings.frame_step <= 0),
      pixel_stride_(settings.pixel_stride),
      limit_bytes_(size_t(settings.keyframe_cache_mb) << 20) {}

void KeyframeSamples::add(const cv::Mat& rgb, const cv::Mat& depth) {
  std::shared_ptr<const FusionSamples> samples;
  if (keep_ && bytes_ < limit_bytes_) {
    samples = std::make_shared<const FusionSamples>(sample_for_fusion(rgb, depth, pixel_stride_));
    bytes_ += samples->bytes();
  }
  samples_.push_back(std::move(samples));
}

void KeyframeSamples::release(const std::function<bool(size_t keyframe)>& culled) {
  for (size_t k = 0; k < samples_.size(); ++k)
    if (samples_[k] && culled(k)) {
      bytes_ -= samples_[k]->bytes();
      samples_[k].reset();
    }
}

std::shared_ptr<const FusionSamples> KeyframeSamples::of(size_t keyframe) const {
  return keyframe < samples_.size() ? samples_[keyframe] : nullptr;
}

}  // namespace slamkit
