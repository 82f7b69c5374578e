#pragma once
// The keyframes' fusion samples, taken while tracking still has their images decoded, so that
// fusing the map need not decode them a second time. Within a memory budget: beyond it a
// keyframe's slot stays empty and fusion loads that keyframe from the sequence again.
#include <cstddef>
#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/settings/fusion_settings.h"
#include "fusion/map_fusion.h"

namespace slamkit {

class KeyframeSamples {
 public:
  KeyframeSamples() = default;
  // Kept only when the map is fused from keyframes alone (settings.frame_step <= 0), within
  // settings.keyframe_cache_mb.
  explicit KeyframeSamples(const FusionSettings& settings);

  // The next keyframe's images (one call per keyframe, in order).
  void add(const cv::Mat& rgb, const cv::Mat& depth);
  // Frees the samples of every keyframe `culled(k)` names: culled keyframes stay out of the
  // fused map, so their samples make room for later ones.
  void release(const std::function<bool(size_t keyframe)>& culled);

  // Keyframe k's samples, or null (over the budget, released, or not kept).
  std::shared_ptr<const FusionSamples> of(size_t keyframe) const;
  size_t size() const { return samples_.size(); }

 private:
  bool keep_ = false;
  int pixel_stride_ = 1;
  size_t limit_bytes_ = 0;
  size_t bytes_ = 0;
  std::vector<std::shared_ptr<const FusionSamples>> samples_;
};

}  // namespace slamkit
