#pragma once
// Depth noise against distance, measured on small planar patches of depth images: a plane is
// fitted to each patch's back-projected points and the spread of the depth residual taken.
// On real data that spread holds the sensor's noise plus the surface's own roughness.
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/camera.h"

namespace slamkit::stats {

struct DepthNoiseSettings {
  int patch = 15;  // side in pixels; the patches tile the image without overlapping
  // A 4-neighbour step larger than this share of the patch's depth is a discontinuity.
  double max_step = 0.05;
  // Curved or folded patches: dropped when a quadric over the PCA plane's axes explains more
  // than this share of the plane's squared residual. Pure noise explains about 3/N of it
  // (N pixels), whatever its size, so unlike a threshold on the PCA eigenvalue ratio, which
  // noise alone raises to ~0.5 for a 15 px patch at 4 m, this keeps noisy far patches.
  double max_curvature_share = 0.2;
  // Patches seen at a grazing angle (cosine of the ray to the PCA normal below this) are
  // dropped: their depth bends across the patch faster than the depth fit follows.
  double min_cos_incidence = 0.2;
  double bin_width = 0.5;  // metres
  double min_depth = 0.5;  // the bins cover [min_depth, max_depth)
  double max_depth = 4.0;
  size_t min_bin_patches = 10;  // bins with fewer patches stay out of the fit
};

struct PatchNoise {
  double depth = 0;  // metres, the patch's mean depth
  double sigma = 0;  // metres, std of the depth (z) residual to the fitted surface
};

// (x/z, y/z) of the ray through every pixel of the raw image, through the lens model: CV_64FC2.
cv::Mat pixel_rays(const Camera& camera);

// The planar patches of one depth image (CV_32F metres, 0 invalid) and their noise; `rays`
// from pixel_rays() for the image's camera.
std::vector<PatchNoise> patch_noise(const cv::Mat& depth, const cv::Mat& rays,
                                    const DepthNoiseSettings& settings);

struct DepthBin {
  double low = 0, high = 0;  // metres
  size_t patches = 0;
  double median_depth = 0;  // metres, of its patches
  double median_sigma = 0;  // metres
};

// The patches by depth bin: count and median noise.
std::vector<DepthBin> bin_noise(const std::vector<PatchNoise>& patches,
                                const DepthNoiseSettings& settings);

// sigma(z) = a + b z^2 (the stereo/structured-light law: depth error grows with z^2).
struct NoiseModel {
  double a = 0;     // metres
  double b = 0;     // 1/metres
  size_t bins = 0;  // bins the fit used
};

// Least squares over the bins' (median depth, median sigma) holding at least
// min_bin_patches patches; nullopt with fewer than two such bins.
std::optional<NoiseModel> fit_noise_model(const std::vector<DepthBin>& bins,
                                          const DepthNoiseSettings& settings);

}  // namespace slamkit::stats
