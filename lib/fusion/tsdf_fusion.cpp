#include "fusion/tsdf_fusion.h"

#include <algorithm>

#include "fusion/fusion_frames.h"
#include "fusion/tsdf_frame.h"
#include "fusion/tsdf_surface.h"
#include "fusion/tsdf_volume.h"

namespace slamkit {

PlyCloud fuse_tsdf(const TumSequence& sequence, std::vector<FusionFrame>& frames,
                   const FusionSettings& settings, FusionReport& report,
                   const std::function<void(size_t, size_t)>& progress) {
  const TsdfFrameMaker maker(sequence.camera(), settings);
  TsdfVolume volume(float(settings.voxel_size), float(settings.truncation));
  const size_t batch_size = size_t(settings.batch_frames);
  std::vector<TsdfFrame> batch(batch_size);
  // A batch's frames are loaded and made ready in parallel, then integrated together (each
  // voxel sees them in frame order).
  for (size_t first = 0; first < frames.size(); first += batch_size) {
    const size_t count = std::min(batch_size, frames.size() - first);
    for_frames_in_parallel(sequence, frames, first, count, settings.pixel_stride,
                           [&](size_t i, const FusionSamples& samples) {
                             batch[i - first] = maker.make(samples);
                           });
    std::vector<const TsdfFrame*> ready;
    std::vector<Eigen::Isometry3d> poses;
    for (size_t i = 0; i < count; ++i) {
      frames[first + i].samples.reset();
      report.raw_points += size_t(std::count_if(batch[i].depth.begin(), batch[i].depth.end(),
                                                [](float d) { return d > 0; }));
      ready.push_back(&batch[i]);
      poses.push_back(frames[first + i].T_w_c);
    }
    volume.integrate(ready, poses);
    if (progress) progress(first + count, frames.size());
  }
  report.blocks = volume.blocks().size();
  report.volume_mb = double(volume.bytes()) / (1 << 20);
  PlyCloud surface = extract_surface(volume, float(settings.min_weight), settings.mesh);
  report.points = surface.points.size();
  report.triangles = surface.triangles.size();
  return surface;
}

}  // namespace slamkit
