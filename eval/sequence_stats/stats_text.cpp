#include "eval/sequence_stats/stats_text.h"

#include <cmath>

namespace slamkit::stats {
namespace {

void print_noise(const SequenceStats& s, std::FILE* out) {
  std::fprintf(out,
               "depth noise  %zu planar patches; median std of the depth residual per bin "
               "(includes surface roughness on real data)\n",
               s.patches);
  for (const DepthBin& b : s.noise_bins) {
    if (b.patches == 0) {
      std::fprintf(out, "  %.1f-%.1f m  %7zu patches\n", b.low, b.high, b.patches);
      continue;
    }
    std::fprintf(out, "  %.1f-%.1f m  %7zu patches  sigma %7.2f mm at %.2f m\n", b.low, b.high,
                 b.patches, 1000 * b.median_sigma, b.median_depth);
  }
  if (s.noise_model)
    std::fprintf(out, "  fit sigma(z) = a + b z^2: a %.2f mm, b %.2f mm/m^2 (%zu bins)\n",
                 1000 * s.noise_model->a, 1000 * s.noise_model->b, s.noise_model->bins);
  else
    std::fprintf(out, "  fit sigma(z) = a + b z^2: too few populated bins\n");
}

void print_sharpness(const SequenceStats& s, std::FILE* out) {
  std::fprintf(out,
               "sharpness    variance of the Laplacian of the grey image: median %.1f; %zu of "
               "%zu frames have an angular speed from groundtruth\n",
               s.median_sharpness, s.frames_with_speed, s.sampled.size());
  for (const SpeedBin& b : s.speed_bins) {
    if (std::isinf(b.high))
      std::fprintf(out, "  %5.0f+    deg/s  %5zu frames", b.low, b.frames);
    else
      std::fprintf(out, "  %5.0f-%-4.0f deg/s  %5zu frames", b.low, b.high, b.frames);
    if (b.frames) std::fprintf(out, "  sharpness %8.1f", b.median_sharpness);
    std::fprintf(out, "\n");
  }
  if (s.sharpness_speed_correlation)
    std::fprintf(out, "  correlation with angular speed (Pearson) %.3f\n",
                 *s.sharpness_speed_correlation);
  else
    std::fprintf(out, "  correlation with angular speed: too few frames with groundtruth\n");
}

}  // namespace

void print_stats(const SequenceStats& s, std::FILE* out) {
  std::fprintf(out, "stats over   %zu sampled frames of %zu\n", s.sampled.size(), s.frames);
  print_noise(s, out);
  std::fprintf(out,
               "invalid      %.2f%% of depth pixels; %.2f%% within depth edges (%.2f%% of "
               "pixels), %.2f%% elsewhere\n",
               100 * s.invalid.share(), 100 * s.invalid.edge_share(),
               100 * s.invalid.edge_region_share(), 100 * s.invalid.off_edge_share());
  print_sharpness(s, out);
  const InlierSummary& m = s.inliers;
  std::fprintf(out,
               "ORB inliers  %zu of %zu consecutive pairs fitted; inlier share median %.3f "
               "(quartiles %.3f, %.3f); median %.0f matches, %.0f with depth\n",
               m.fitted, m.pairs, m.median, m.q1, m.q3, m.median_matches, m.median_correspondences);
}

}  // namespace slamkit::stats
