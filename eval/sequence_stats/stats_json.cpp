#include "eval/sequence_stats/stats_json.h"

#include <cmath>

namespace slamkit::stats {
namespace {

template <typename T>
nlohmann::json or_null(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json noise_json(const SequenceStats& s) {
  nlohmann::json bins = nlohmann::json::array();
  for (const DepthBin& b : s.noise_bins)
    bins.push_back({{"low", b.low},
                    {"high", b.high},
                    {"patches", b.patches},
                    {"median_depth", b.median_depth},
                    {"median_sigma", b.median_sigma}});
  nlohmann::json fit = nullptr;
  if (s.noise_model)
    fit = {{"a", s.noise_model->a}, {"b", s.noise_model->b}, {"bins", s.noise_model->bins}};
  return {{"patches", s.patches}, {"bins", bins}, {"fit", fit}};
}

nlohmann::json sharpness_json(const SequenceStats& s) {
  nlohmann::json bins = nlohmann::json::array();
  for (const SpeedBin& b : s.speed_bins)
    bins.push_back({{"low", b.low},
                    {"high", std::isinf(b.high) ? nlohmann::json(nullptr) : nlohmann::json(b.high)},
                    {"frames", b.frames},
                    {"median_sharpness", b.median_sharpness}});
  return {{"measure", "laplacian_variance"},
          {"median", s.median_sharpness},
          {"frames_with_speed", s.frames_with_speed},
          {"bins", bins},
          {"correlation", or_null(s.sharpness_speed_correlation)}};
}

nlohmann::json frame_json(const FrameRecord& f) {
  nlohmann::json pair = nullptr;
  if (f.pair)
    pair = {{"matches", f.pair->matches},
            {"correspondences", f.pair->correspondences},
            {"inliers", f.pair->inliers},
            {"fitted", f.pair->fitted}};
  return {{"index", f.index},
          {"stamp", f.stamp},
          {"sharpness", f.sharpness},
          {"angular_speed", or_null(f.angular_speed)},
          {"planar_patches", f.planar_patches},
          {"pair", pair}};
}

}  // namespace

nlohmann::json stats_json(const SequenceStats& s, const std::string& sequence) {
  const InvalidCounts& v = s.invalid;
  const InlierSummary& m = s.inliers;
  nlohmann::json frames = nlohmann::json::array();
  for (const FrameRecord& f : s.sampled) frames.push_back(frame_json(f));
  return {{"sequence", sequence},
          {"frames", s.frames},
          {"sampled", s.sampled.size()},
          {"depth_noise", noise_json(s)},
          {"invalid_depth",
           {{"pixels", v.pixels},
            {"invalid", v.invalid},
            {"edge_pixels", v.edge_pixels},
            {"edge_invalid", v.edge_invalid},
            {"share", v.share()},
            {"edge_region_share", v.edge_region_share()},
            {"edge_share", v.edge_share()},
            {"off_edge_share", v.off_edge_share()}}},
          {"sharpness", sharpness_json(s)},
          {"match_inliers",
           {{"pairs", m.pairs},
            {"fitted", m.fitted},
            {"q1", m.q1},
            {"median", m.median},
            {"q3", m.q3},
            {"median_matches", m.median_matches},
            {"median_correspondences", m.median_correspondences}}},
          {"per_frame", frames}};
}

}  // namespace slamkit::stats
