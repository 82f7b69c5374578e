#pragma once
// A frame made ready for TSDF integration (docs/method.md#map-fusion): its sampled depth in
// ideal pinhole geometry at the sample resolution, each sample's weight from the depth noise
// model, and its colour; samples at depth edges (flying pixels among them) left out.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/camera.h"
#include "core/settings/fusion_settings.h"
#include "fusion/map_fusion.h"

namespace slamkit {

// The sample image's pinhole intrinsics: pixel (i, j) of it is raw pixel (i s, j s), s the
// pixel stride.
struct SampleIntrinsics {
  int width = 0, height = 0;
  float fx = 0, fy = 0, cx = 0, cy = 0;
};

// Weights are counted in 1/256 of a head-on measurement at 1 m.
constexpr float kTsdfWeightUnits = 256;

struct TsdfFrame {
  SampleIntrinsics intrinsics;
  std::vector<float> depth;   // metres, 0 = none (invalid, beyond max_depth or at an edge)
  std::vector<uint16_t> weight;  // in kTsdfWeightUnits, >= 1 where depth is
  std::vector<uint8_t> rgb;   // 3 per sample
};

class TsdfFrameMaker {
 public:
  TsdfFrameMaker(const Camera& camera, const FusionSettings& settings);

  // `samples` as sample_for_fusion took them (raw lens geometry) at settings.pixel_stride.
  TsdfFrame make(const FusionSamples& samples) const;
  const SampleIntrinsics& intrinsics() const { return intrinsics_; }

 private:
  uint16_t weight_of(float z, float cos_incidence) const;
  // Each depth replaced by the value at it of a plane fitted to the samples around it on the
  // same surface (within smoothing_radius, no edge between).
  std::vector<float> smoothed(const std::vector<float>& z) const;

  SampleIntrinsics intrinsics_;
  int raw_width_ = 0;            // samples per row of FusionSamples
  std::vector<int32_t> source_;  // per ideal sample: its raw sample (-1: outside); empty = same
  std::vector<Eigen::Vector3f> rays_;  // per ideal sample: (x/z, y/z, 1)
  // The incidence angle at cos = i / kIncidenceSteps (within 0.002 rad of acos's).
  static constexpr int kIncidenceSteps = 1024;
  std::vector<float> incidence_;
  float max_depth_, edge_jump_;
  int smoothing_radius_;
  bool noise_weighting_;
};

}  // namespace slamkit
