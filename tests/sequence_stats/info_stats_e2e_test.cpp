// `slamkit info --stats` end to end: on a synthetic sequence whose sensor model is known, on
// the real fr2/desk piece, and on bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "datasets/synth/sensor_model.h"
#include "io/tum_sequence.h"
#include "support/synthetic_sequence.h"
#include "support/test_data.h"

namespace slamkit::stats {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The populated depth bin with the most patches.
nlohmann::json fullest_bin(const nlohmann::json& stats) {
  nlohmann::json best;
  for (const auto& bin : stats["depth_noise"]["bins"])
    if (best.is_null() || bin["patches"] > best["patches"]) best = bin;
  return best;
}

TEST(InfoStats, SyntheticSequenceShowsItsSensorModelsNoise) {
  const fs::path sequence = test::synthetic_sequence(synth::Preset::kDesk, 10);
  const fs::path json = test::temp_dir("info_stats") / "stats.json";
  const test::SlamkitResult run =
      test::run_slamkit_apart("info --stats " + quoted(sequence) + " --json " + quoted(json));
  ASSERT_EQ(run.code, 0) << run.err;
  for (const char* line : {"frames      10", "depth noise", "fit sigma(z) = a + b z^2", "invalid",
                           "sharpness", "correlation", "ORB inliers"})
    EXPECT_NE(run.out.find(line), std::string::npos) << line << "\n" << run.out;

  const nlohmann::json stats = read_json(json);
  EXPECT_EQ(stats["frames"], 10);
  EXPECT_EQ(stats["sampled"], 10);
  EXPECT_EQ(stats["per_frame"].size(), 10u);
  EXPECT_EQ(stats["sharpness"]["frames_with_speed"], 10);
  EXPECT_GT(stats["sharpness"]["median"].get<double>(), 0.0);
  // The renderer's depth noise is SensorModel::depth_sigma: the fullest bin finds it.
  const nlohmann::json bin = fullest_bin(stats);
  ASSERT_GT(bin["patches"].get<int>(), 100);
  const double expected = synth::SensorModel::depth_sigma(bin["median_depth"].get<double>());
  EXPECT_NEAR(bin["median_sigma"].get<double>(), expected, 0.15 * expected) << bin;
  EXPECT_FALSE(stats["depth_noise"]["fit"].is_null());
  // Missing depth: the model's dropouts, holes and grazing surfaces only.
  EXPECT_GT(stats["invalid_depth"]["share"].get<double>(), 0.0);
  EXPECT_LT(stats["invalid_depth"]["share"].get<double>(), 0.1);
  const nlohmann::json& inliers = stats["match_inliers"];
  EXPECT_EQ(inliers["pairs"], 9);  // the last frame has no successor
  EXPECT_EQ(inliers["fitted"], 9);
  EXPECT_GT(inliers["median"].get<double>(), 0.9);
  EXPECT_LE(inliers["q1"].get<double>(), inliers["median"].get<double>());
  EXPECT_LE(inliers["median"].get<double>(), inliers["q3"].get<double>());
}

TEST(InfoStats, RealFr2DeskHasKinectLikeNoiseAndConsistentMatches) {
  SLAMKIT_REQUIRE_DATA(sequence, "rgbd_dataset_freiburg2_desk_first50");
  const fs::path json = test::temp_dir("info_stats_fr2") / "stats.json";
  const test::SlamkitResult run =
      test::run_slamkit_apart("info --stats " + quoted(sequence) +
                              " --depth-scale 5208 --sample 10 --json " + quoted(json));
  ASSERT_EQ(run.code, 0) << run.err;
  const nlohmann::json stats = read_json(json);
  EXPECT_EQ(stats["sampled"], 10);
  // Kinect v1: depth error grows as z^2, with b about 1.5-2 mm/m^2 in the literature; the
  // residual here also holds the desk's roughness. Loose bounds: the sign and the magnitude.
  const nlohmann::json& fit = stats["depth_noise"]["fit"];
  ASSERT_FALSE(fit.is_null());
  EXPECT_GT(fit["b"].get<double>(), 0.0005);
  EXPECT_LT(fit["b"].get<double>(), 0.005);
  EXPECT_GT(stats["invalid_depth"]["share"].get<double>(), 0.05);  // a real sensor loses pixels
  EXPECT_EQ(stats["sharpness"]["frames_with_speed"], 10);
  EXPECT_GT(stats["match_inliers"]["median"].get<double>(), 0.8);
}

TEST(InfoStats, BadInputExitsNonZeroNamingTheFile) {
  const fs::path dir = test::temp_dir("info_stats_bad");
  const test::SlamkitResult missing =
      test::run_slamkit_apart("info --stats " + quoted(dir / "no_such_sequence"));
  EXPECT_NE(missing.code, 0);
  EXPECT_NE(missing.err.find("no_such_sequence"), std::string::npos) << missing.err;

  const fs::path sequence = test::synthetic_sequence(synth::Preset::kDesk, 10);
  const fs::path unwritable = dir / "no_such_folder" / "stats.json";
  const test::SlamkitResult json = test::run_slamkit_apart(
      "info --stats " + quoted(sequence) + " --sample 2 --json " + quoted(unwritable));
  EXPECT_NE(json.code, 0);
  EXPECT_NE(json.err.find(unwritable.string()), std::string::npos) << json.err;

  // Frame 1's depth gone: only the statistics read it (the pair of sampled frame 0).
  const fs::path copy = dir / "desk10";
  fs::copy(sequence, copy, fs::copy_options::recursive);
  const TumSequence opened = TumSequence::open(copy);
  const fs::path lost = copy / opened.files(1).depth.file;
  fs::remove(lost);
  const test::SlamkitResult frame =
      test::run_slamkit_apart("info --stats " + quoted(copy) + " --sample 2");
  EXPECT_EQ(frame.code, 2);
  EXPECT_NE(frame.err.find(lost.filename().string()), std::string::npos) << frame.err;

  const test::SlamkitResult without_stats =
      test::run_slamkit_apart("info " + quoted(sequence) + " --json " + quoted(dir / "s.json"));
  EXPECT_NE(without_stats.code, 0);
  EXPECT_NE(without_stats.err.find("--stats"), std::string::npos) << without_stats.err;
}

}  // namespace
}  // namespace slamkit::stats
