#include "datasets/synth/map_quality.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "datasets/synth/trajectory_presets.h"
#include "support/test_data.h"
#include "synth/shared_room.h"

namespace slamkit::synth {
namespace {

namespace fs = std::filesystem;

struct Hit {
  Eigen::Vector3f point, normal;
};

const std::vector<Eigen::Isometry3d>& poses() {
  static const std::vector<Eigen::Isometry3d> p = make_trajectory(Preset::kDesk, 30, 1);
  return p;
}

// What a perfect sensor sees from every 10th pose through every 2nd pixel up to 3 m: a map
// lying exactly on the surfaces (a superset of the evaluation's every-8th-pixel samples).
const std::vector<Hit>& perfect_hits() {
  static const std::vector<Hit> hits = [] {
    const Camera camera = synthetic_camera();
    std::vector<Hit> out;
    for (size_t i = 0; i < poses().size(); i += 10)
      for (int v = 0; v < camera.height; v += 2)
        for (int u = 0; u < camera.width; u += 2) {
          const Eigen::Vector3d ray = poses()[i].linear() * camera.back_project({u, v}, 1.0);
          const auto hit = test::shared_room().cast_ray(poses()[i].translation(), ray);
          if (hit && hit->t <= 3.0)
            out.push_back({hit->point.cast<float>(), hit->normal.cast<float>()});
        }
    return out;
  }();
  return hits;
}

// The perfect map with point i moved offset(i) metres off its surface, towards the camera.
template <typename Offset>
std::vector<Eigen::Vector3f> displaced_map(Offset offset) {
  std::vector<Eigen::Vector3f> map;
  for (size_t i = 0; i < perfect_hits().size(); ++i)
    map.push_back(perfect_hits()[i].point + float(offset(i)) * perfect_hits()[i].normal);
  return map;
}

MapQuality evaluate(const std::vector<Eigen::Vector3f>& map) {
  return evaluate_map_quality(map, test::shared_room(), poses(), synthetic_camera());
}

TEST(MapQuality, APerfectMapIsExactAndComplete) {
  const MapQuality q = evaluate(displaced_map([](size_t) { return 0.0; }));
  EXPECT_EQ(q.map_points, perfect_hits().size());
  EXPECT_LT(q.accuracy_max, 1e-5);  // float rounding of the points only
  EXPECT_EQ(q.views, 3u);
  EXPECT_GT(q.surface_samples, 5000u);
  EXPECT_EQ(q.covered_samples, q.surface_samples);
  EXPECT_EQ(q.completeness, 1.0);
}

TEST(MapQuality, AccuracyStatisticsFollowTheDistances) {
  // Offsets spread evenly over 0..4 mm: median 2 mm, p95 3.8 mm, max 4 mm. Points near an
  // edge may lie closer to another face, so the statistics can only come out a little lower.
  const size_t n = perfect_hits().size();
  const MapQuality q = evaluate(displaced_map([n](size_t i) { return 0.004 * i / (n - 1); }));
  EXPECT_NEAR(q.accuracy_mean, 0.002, 1e-4);
  EXPECT_NEAR(q.accuracy_median, 0.002, 1e-4);
  EXPECT_NEAR(q.accuracy_p95, 0.0038, 1e-4);
  EXPECT_NEAR(q.accuracy_max, 0.004, 1e-6);
  EXPECT_EQ(q.completeness, 1.0);  // 4 mm is well within the 2 cm radius
}

TEST(MapQuality, CompletenessCountsOnlyCoveredSurface) {
  // 3 cm off the surface covers nothing (bar corners, where another face's points come close).
  EXPECT_LT(evaluate(displaced_map([](size_t) { return 0.03; })).completeness, 0.1);
  // Half the room mapped: about the share of the seen surface on that side.
  std::vector<Eigen::Vector3f> half;
  size_t west = 0;
  for (const Hit& h : perfect_hits()) {
    if (h.point.x() < 0) half.push_back(h.point);
    west += h.point.x() < 0;
  }
  const double share = double(west) / double(perfect_hits().size());
  ASSERT_GT(share, 0.1);
  ASSERT_LT(share, 0.9);
  EXPECT_NEAR(evaluate(half).completeness, share, 0.1);
  const MapQuality empty = evaluate({});
  EXPECT_EQ(empty.completeness, 0.0);
  EXPECT_EQ(empty.accuracy_max, 0.0);
}

TEST(MapQuality, JsonHoldsTheNumbersUnderMap) {
  const MapQuality q = evaluate(displaced_map([](size_t) { return 0.001; }));
  nlohmann::json metrics = {{"ate", {{"rmse", 0.01}}}};
  add_map_quality_json(metrics, q);
  EXPECT_EQ(metrics["ate"]["rmse"], 0.01);  // other sections untouched
  EXPECT_EQ(metrics["map"]["points"], q.map_points);
  EXPECT_EQ(metrics["map"]["accuracy"]["median"], q.accuracy_median);
  EXPECT_EQ(metrics["map"]["completeness"], q.completeness);
  EXPECT_EQ(metrics["map"]["settings"]["radius"], 0.02);
}

TEST(SyntheticInfo, RoundTripAndErrorsNamingTheFile) {
  const fs::path dir = slamkit::test::temp_dir("synthetic_info");
  EXPECT_FALSE(read_synthetic_info(dir));
  SequenceSpec spec;
  spec.preset = Preset::kLowTexture;
  spec.frames = 123;
  spec.seed = 9;
  write_synthetic_info(dir, spec);
  const auto info = read_synthetic_info(dir);
  ASSERT_TRUE(info);
  EXPECT_EQ(info->scene, "furnished_room");
  EXPECT_EQ(info->preset, Preset::kLowTexture);
  EXPECT_EQ(info->frames, 123);
  EXPECT_EQ(info->seed, 9u);

  const fs::path file = dir / kSyntheticInfoFile;
  for (const std::string text :
       {"scene: furnished_room\npreset: desk\n",
        "scene: furnished_room\npreset: nowhere\nframes: 2\nseed: 1\n", "[unclosed"}) {
    std::ofstream(file, std::ios::trunc) << text;
    try {
      read_synthetic_info(dir);
      ADD_FAILURE() << "expected InputError for: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
  }
  SyntheticInfo other;
  other.scene = "castle";
  EXPECT_THROW(make_scene(other), InputError);
}

}  // namespace
}  // namespace slamkit::synth
