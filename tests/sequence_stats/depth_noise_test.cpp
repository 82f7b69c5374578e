// Depth noise on planes of known noise: the per-bin sigma and the a + b z^2 fit come back.
#include "eval/sequence_stats/depth_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "datasets/synth/sequence_writer.h"

namespace slamkit::stats {
namespace {

// The synthetic sequences' camera: fx = fy = 525, 640 x 480, no distortion.
Camera pinhole() { return synth::synthetic_camera(); }

constexpr double kA = 0.001, kB = 0.002;  // the noise law the images are drawn with
double true_sigma(double z) { return kA + kB * z * z; }

// The plane n . p = d seen by `camera` (normal towards the camera), with Gaussian depth noise of
// true_sigma(z) along each ray.
cv::Mat noisy_plane(const Camera& camera, const Eigen::Vector3d& n, double d, cv::RNG& rng) {
  cv::Mat depth(camera.height, camera.width, CV_32F);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      const Eigen::Vector3d ray((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      const double z = d / n.dot(ray);
      depth.at<float>(v, u) = float(z + rng.gaussian(true_sigma(z)));
    }
  return depth;
}

TEST(DepthNoise, MedianSigmaPerBinMatchesTheNoiseOfFrontoParallelPlanes) {
  const Camera camera = pinhole();
  const cv::Mat rays = pixel_rays(camera);
  const DepthNoiseSettings settings;
  cv::RNG rng(7);
  std::vector<PatchNoise> patches;
  for (const double z : {1.0, 2.0, 3.0}) {
    const auto found = patch_noise(noisy_plane(camera, {0, 0, 1}, z, rng), rays, settings);
    EXPECT_GT(found.size(), 1000u) << "planar patches at " << z << " m";
    patches.insert(patches.end(), found.begin(), found.end());
  }
  const std::vector<DepthBin> bins = bin_noise(patches, settings);
  ASSERT_EQ(bins.size(), 7u);  // 0.5 m bins over [0.5, 4)
  for (const DepthBin& bin : bins) {
    if (bin.patches == 0) continue;
    EXPECT_NEAR(bin.median_sigma, true_sigma(bin.median_depth), 0.10 * true_sigma(bin.median_depth))
        << "bin " << bin.low << "-" << bin.high;
  }
  // The planes sit on bin edges: each fills the bins on both sides of its depth.
  size_t binned = 0;
  for (const size_t k : {0, 1, 2, 3, 4, 5}) binned += bins[k].patches;
  EXPECT_EQ(binned, patches.size());
  EXPECT_EQ(bins[6].patches, 0u);

  const auto model = fit_noise_model(bins, settings);
  ASSERT_TRUE(model);
  EXPECT_EQ(model->bins, 6u);
  EXPECT_NEAR(model->a, kA, 0.15 * kA);
  EXPECT_NEAR(model->b, kB, 0.05 * kB);
}

TEST(DepthNoise, TiltedPlaneResidualIsTakenAlongTheRay) {
  // 40 degrees from fronto-parallel: the residual across the surface would be cos(40) = 0.77
  // of the depth noise.
  const Camera camera = pinhole();
  const double tilt = 40.0 * M_PI / 180.0;
  const Eigen::Vector3d n(std::sin(tilt), 0, std::cos(tilt));
  cv::RNG rng(11);
  const auto patches =
      patch_noise(noisy_plane(camera, n, 2.0 * std::cos(tilt), rng), pixel_rays(camera), {});
  ASSERT_GT(patches.size(), 500u);
  for (const PatchNoise& p : patches) ASSERT_GT(p.sigma, 0);
  std::vector<double> ratio;
  for (const PatchNoise& p : patches) ratio.push_back(p.sigma / true_sigma(p.depth));
  std::nth_element(ratio.begin(), ratio.begin() + long(ratio.size() / 2), ratio.end());
  EXPECT_NEAR(ratio[ratio.size() / 2], 1.0, 0.10);
}

TEST(DepthNoise, DiscontinuitiesCurvedSurfacesAndHolesAreNotPlanarPatches) {
  const Camera camera = pinhole();
  const cv::Mat rays = pixel_rays(camera);
  DepthNoiseSettings settings;
  // A step from 1 m to 2 m every 15 columns, offset so that every patch straddles one.
  cv::Mat steps(camera.height, camera.width, CV_32F);
  for (int u = 0; u < steps.cols; ++u) steps.col(u).setTo(((u + 7) / 15) % 2 ? 2.0 : 1.0);
  EXPECT_TRUE(patch_noise(steps, rays, settings).empty());

  // A noiseless cylinder of radius 5 cm around the vertical axis, 1 m away: smooth, not planar.
  cv::Mat cylinder(camera.height, camera.width, CV_32F);
  for (int v = 0; v < cylinder.rows; ++v)
    for (int u = 0; u < cylinder.cols; ++u) {
      const double x = (u - camera.cx) / camera.fx;  // ray (x, ., 1) meets x^2 + (z-1.05)^2 = r^2
      const double qa = x * x + 1, qb = -2 * 1.05, qc = 1.05 * 1.05 - 0.05 * 0.05;
      const double disc = qb * qb - 4 * qa * qc;
      cylinder.at<float>(v, u) = disc > 0 ? float((-qb - std::sqrt(disc)) / (2 * qa)) : 0.0f;
    }
  EXPECT_TRUE(patch_noise(cylinder, rays, settings).empty());

  // A plane with one invalid pixel in every patch.
  cv::Mat holes(camera.height, camera.width, CV_32F, cv::Scalar(1.5));
  for (int v = 7; v < holes.rows; v += 15)
    for (int u = 7; u < holes.cols; u += 15) holes.at<float>(v, u) = 0;
  EXPECT_TRUE(patch_noise(holes, rays, settings).empty());
  // The same plane without holes: every patch, noiseless.
  const auto whole =
      patch_noise(cv::Mat(camera.height, camera.width, CV_32F, cv::Scalar(1.5)), rays, settings);
  EXPECT_EQ(whole.size(), size_t(32 * 42));
  for (const PatchNoise& p : whole) EXPECT_NEAR(p.sigma, 0.0, 1e-6);
}

TEST(DepthNoise, FitNeedsTwoPopulatedBins) {
  const DepthNoiseSettings settings;
  std::vector<DepthBin> bins(2);
  bins[0] = {1.0, 1.5, 50, 1.2, 0.003};
  bins[1] = {2.0, 2.5, settings.min_bin_patches - 1, 2.2, 0.01};
  EXPECT_FALSE(fit_noise_model(bins, settings));
  bins[1].patches = settings.min_bin_patches;
  const auto model = fit_noise_model(bins, settings);
  ASSERT_TRUE(model);
  EXPECT_NEAR(model->a + model->b * 1.44, 0.003, 1e-12);  // two points: an exact fit
  EXPECT_NEAR(model->a + model->b * 4.84, 0.01, 1e-12);
}

}  // namespace
}  // namespace slamkit::stats
