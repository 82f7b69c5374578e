#include "settings/settings_yaml.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "settings/settings_fields.h"
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
  expect_error("tracking:\n  ransac:\n    seed: abc\n",
               "bad.yaml:3: tracking.ransac.seed has the wrong type");
  expect_error("orb:\n  fast_type: fast7\n", "bad.yaml:2: 'fast7' is not a value of orb.fast_type");
  expect_error("orbs: {}\n", "unknown setting 'orbs'");
  expect_error("orb: [1, 2]\n", "orb must be a map");
}

TEST(SettingsYaml, RejectsValuesOutsideTheirRangeNamingFileLineKeyValueAndRange) {
  expect_error("orb:\n  num_features: -5\n",
               "bad.yaml:2: orb.num_features: -5 is outside 1..100000");
  expect_error("orb:\n  num_features: 0\n", "bad.yaml:2: orb.num_features: 0 is outside 1..100000");
  expect_error("pipeline:\n  threads: -3\n", "bad.yaml:2: pipeline.threads: -3 is outside 0..inf");
  expect_error("pipeline:\n  chunk_frames: 0\n",
               "bad.yaml:2: pipeline.chunk_frames: 0 is outside 1..inf");
  expect_error("tracking:\n  point_to_plane:\n    iterations_per_level: -1\n",
               "bad.yaml:3: tracking.point_to_plane.iterations_per_level: -1 is outside 1..1000");
  expect_error("orb:\n  pyramid_levels: 40\n",
               "bad.yaml:2: orb.pyramid_levels: 40 is outside 1..12");
  expect_error("orb:\n  scale_factor: .nan\n",
               "bad.yaml:2: orb.scale_factor: .nan is outside 1 (excluded)..2");
  expect_error("orb:\n  scale_factor: 1\n", "orb.scale_factor: 1 is outside 1 (excluded)..2");
  expect_error("map:\n  voxel_size: .inf\n",
               "bad.yaml:2: map.voxel_size: .inf is outside 0 (excluded)..inf");
}

TEST(SettingsYaml, RangeBoundsThemselvesAreAccepted) {
  const fs::path dir = test::temp_dir("settings");
  std::ofstream(dir / "s.yaml") << "orb:\n  num_features: 1\n  pyramid_levels: 12\n  "
                                   "scale_factor: 2\npipeline:\n  threads: 0\n";
  Settings s;
  read_settings_yaml(dir / "s.yaml", s);
  EXPECT_EQ(s.orb.num_features, 1);
  EXPECT_EQ(s.orb.pyramid_levels, 12);
  EXPECT_EQ(s.orb.scale_factor, 2.0);
}

// Walks every field of a Settings, checking each ranged one's value.
class DefaultChecker {
 public:
  template <class T>
  void field(const char*, T&, const SettingNote&) {}
  template <class T>
  void field(const char* name, T& value, const Range& range, const SettingNote&) {
    ++checked;
    EXPECT_TRUE(in_range(double(value), range))
        << prefix_ << name << " = " << value << " is outside " << range_text(range);
  }
  template <class S>
  void section(const char* name, S& settings, const char*) {
    const std::string outer = prefix_;
    prefix_ += std::string(name) + ".";
    visit_fields(settings, *this);
    prefix_ = outer;
  }
  int checked = 0;

 private:
  std::string prefix_;
};

TEST(SettingsYaml, EveryDefaultLiesInsideItsRange) {
  Settings defaults;
  DefaultChecker checker;
  visit_fields(defaults, checker);
  EXPECT_GT(checker.checked, 80);  // the walk reached every section
}

}  // namespace
}  // namespace slamkit
