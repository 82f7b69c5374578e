// `slamkit eval kitti` end to end, on a hand-worked case: KITTI files of a straight 1 m-step
// drive along z, the estimate 1 % too long.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

fs::path write_straight_kitti(const fs::path& path, size_t n, double step) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  for (size_t k = 0; k < n; ++k)
    std::fprintf(f, "1 0 0 0 0 1 0 0 0 0 1 %.17g\n", step * double(k));
  std::fclose(f);
  return path;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(EvalKitti, ScaleErrorGivesTheDevkitsPercentPerLength) {
  const fs::path dir = test::temp_dir("eval_kitti");
  const fs::path gt = write_straight_kitti(dir / "gt.txt", 1000, 1.0);
  const fs::path est = write_straight_kitti(dir / "est.txt", 1000, 1.01);
  const test::SlamkitResult r = test::run_slamkit_apart("eval kitti " + quoted(gt) + " " +
                                                        quoted(est) + " --out " +
                                                        quoted(dir / "run"));
  ASSERT_EQ(r.code, 0) << r.err;
  // A segment of L m from frame f ends at f + L + 1 (the first frame beyond L m), so the
  // estimate is 0.01 (L + 1) m off over L m; starts every 10 frames while f + L + 1 < 1000.
  EXPECT_NE(r.out.find("kitti.100m 1.010000 % 0.000000 deg/m (90 segments)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("kitti.800m 1.001250 % 0.000000 deg/m (20 segments)"), std::string::npos)
      << r.out;
  std::ifstream in(dir / "run" / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  const nlohmann::json& k = m["kitti"];
  ASSERT_EQ(k["lengths"].size(), 8u);
  double sum = 0;
  size_t count = 0;
  for (const auto& l : k["lengths"]) {
    const double length = l["length_m"];
    EXPECT_NEAR(l["trans_pct"].get<double>(), (length + 1) / length, 1e-9) << length;
    sum += l["segments"].get<double>() * (length + 1) / length;
    count += l["segments"].get<size_t>();
  }
  EXPECT_EQ(k["segments"], count);
  EXPECT_EQ(k["pairs"], 1000);
  EXPECT_NEAR(k["trans_pct"].get<double>(), sum / double(count), 1e-9);
  EXPECT_EQ(k["rot_deg_per_m"], 0.0);
  EXPECT_EQ(m["inputs"]["groundtruth"]["format"], "kitti");
  EXPECT_EQ(m["inputs"]["groundtruth"]["times"], "pose index");
}

TEST(EvalKitti, PathTooShortExits2NamingTheGroundtruth) {
  const fs::path dir = test::temp_dir("eval_kitti");
  const fs::path gt = write_straight_kitti(dir / "gt.txt", 101, 1.0);  // exactly 100 m
  const test::SlamkitResult r =
      test::run_slamkit_apart("eval kitti " + quoted(gt) + " " + quoted(gt));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("gt.txt: groundtruth path over the 101 matched frames is 100.000 m"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

}  // namespace
}  // namespace slamkit::eval
