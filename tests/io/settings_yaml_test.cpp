#include "io/settings_yaml.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SettingsYaml, RoundTripsEveryField) {
  const fs::path dir = test::temp_dir("settings");
  Settings changed;
  changed.orb.num_features = 1234;
  changed.orb.scale_factor = 1.25;
  changed.orb.fast_type = FastType::kFast9;
  changed.matcher.backend = MatcherBackend::kBruteForce;
  changed.tracking.ransac.threshold_base = 0.0125;
  changed.tracking.point_to_plane.iterations_per_level = 5;
  changed.keyframes.similarity_threshold = 0.65;
  changed.keyframes.pattern_seed = 123456789012345ull;
  changed.pipeline.threads = 2;
  write_settings_yaml(dir / "a.yaml", changed);

  Settings read;
  read_settings_yaml(dir / "a.yaml", read);
  EXPECT_EQ(read.orb.num_features, 1234);
  EXPECT_EQ(read.orb.scale_factor, 1.25);
  EXPECT_EQ(read.orb.fast_type, FastType::kFast9);
  EXPECT_EQ(read.matcher.backend, MatcherBackend::kBruteForce);
  EXPECT_EQ(read.tracking.ransac.threshold_base, 0.0125);
  EXPECT_EQ(read.tracking.point_to_plane.iterations_per_level, 5);
  EXPECT_EQ(read.keyframes.similarity_threshold, 0.65);
  EXPECT_EQ(read.keyframes.pattern_seed, 123456789012345ull);
  EXPECT_EQ(read.pipeline.threads, 2);
  // Every other field too: writing what was read gives the same file.
  write_settings_yaml(dir / "b.yaml", read);
  EXPECT_EQ(read_text(dir / "a.yaml"), read_text(dir / "b.yaml"));
}

TEST(SettingsYaml, PartialFileKeepsDefaults) {
  const fs::path dir = test::temp_dir("settings");
  std::ofstream(dir / "s.yaml") << "orb:\n  num_features: 500\n";
  Settings s;
  read_settings_yaml(dir / "s.yaml", s);
  EXPECT_EQ(s.orb.num_features, 500);
  EXPECT_EQ(s.orb.pyramid_levels, 4);
  EXPECT_EQ(s.tracking.min_pairs_for_svd, 50);
  EXPECT_EQ(s.keyframes.similarity_threshold, 0.7);
}

void expect_error(const std::string& text, const std::string& fragment) {
  const fs::path dir = test::temp_dir("settings");
  std::ofstream(dir / "bad.yaml") << text;
  Settings s;
  try {
    read_settings_yaml(dir / "bad.yaml", s);
    FAIL() << "no error for: " << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SettingsYaml, RejectsTyposWrongTypesAndBadEnumsNamingTheLine) {
  expect_error("orb:\n  num_feature: 500\n", "bad.yaml:2: unknown setting 'orb.num_feature'");
  expect_error("tracking:\n  ransac:\n    seed: abc\n", "bad.yaml:3: tracking.ransac.seed has the wrong type");
  expect_error("orb:\n  fast_type: fast7\n", "bad.yaml:2: 'fast7' is not a value of orb.fast_type");
  expect_error("orbs: {}\n", "unknown setting 'orbs'");
  expect_error("orb: [1, 2]\n", "orb must be a map");
}

}  // namespace
}  // namespace slamkit
