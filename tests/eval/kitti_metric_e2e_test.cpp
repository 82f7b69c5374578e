// `slamkit eval kitti` end to end: a hand-worked case (a straight 1 m-step drive along z, the
// estimate 1 % too long) and a winding drive against a numpy re-implementation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "generated_trajectories.h"
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

// A winding 1500 m drive in the x-z plane (KITTI's ground plane) and an estimate with a
// heading drift and a 2 % scale error, printed as KITTI prints its poses (7 digits).
fs::path write_winding_kitti(const fs::path& path, bool estimate) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < 1500; ++k) {
    const double s = double(k);
    double yaw = 0.8 * std::sin(s / 200.0);
    if (estimate) yaw += 1e-4 * s + 0.01 * std::sin(s / 30.0);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).matrix();
    test_files::write_kitti_pose(f, R, position);
    position += (estimate ? 1.02 : 1.0) * (R * Eigen::Vector3d::UnitZ());
  }
  std::fclose(f);
  return path;
}

// Against an independent numpy re-implementation (kitti_odometry_reference.py).
TEST(EvalKitti, MatchesAnIndependentNumpyImplementation) {
  const char* python = "/usr/bin/python3";
  if (std::system((std::string(python) + " -c 'import numpy' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << python << " with numpy not found";
  const fs::path dir = test::temp_dir("eval_kitti");
  const fs::path gt = write_winding_kitti(dir / "gt.txt", false);
  const fs::path est = write_winding_kitti(dir / "est.txt", true);
  const fs::path script =
      fs::path(SLAMKIT_SOURCE_DIR) / "tests" / "eval" / "kitti_odometry_reference.py";
  ASSERT_EQ(std::system((std::string(python) + " " + quoted(script) + " " + quoted(gt) + " " +
                         quoted(est) + " > " + quoted(dir / "reference.json"))
                            .c_str()),
            0);
  ASSERT_EQ(test::run_slamkit("eval kitti " + quoted(gt) + " " + quoted(est) + " --quiet --json " +
                              quoted(dir / "metrics.json")),
            0);
  std::ifstream reference_file(dir / "reference.json"), metrics_file(dir / "metrics.json");
  const nlohmann::json reference = nlohmann::json::parse(reference_file);
  const nlohmann::json k = nlohmann::json::parse(metrics_file)["kitti"];
  EXPECT_EQ(k["segments"], reference["segments"]);
  EXPECT_GT(k["trans_pct"].get<double>(), 1.0);  // the errors are real, not zero
  EXPECT_GT(k["rot_deg_per_m"].get<double>(), 1e-3);
  const auto near = [](const nlohmann::json& a, const nlohmann::json& b) {
    EXPECT_NEAR(a.get<double>(), b.get<double>(), 1e-9 * std::abs(b.get<double>())) << b;
  };
  near(k["trans_pct"], reference["trans_pct"]);
  near(k["rot_deg_per_m"], reference["rot_deg_per_m"]);
  ASSERT_EQ(k["lengths"].size(), reference["lengths"].size());
  for (size_t i = 0; i < k["lengths"].size(); ++i) {
    EXPECT_EQ(k["lengths"][i]["segments"], reference["lengths"][i]["segments"]);
    near(k["lengths"][i]["trans_pct"], reference["lengths"][i]["trans_pct"]);
    near(k["lengths"][i]["rot_deg_per_m"], reference["lengths"][i]["rot_deg_per_m"]);
  }
}

// Against the devkit itself: evaluate_odometry.cpp (KITTI odometry devkit, as in
// alexkreimer/odometry devkit/cpp) built with double for float, its arithmetic otherwise as
// is, on the generated drive printed with KITTI's 7 digits (poses/00.txt = gt.txt,
// results/00.txt = est.txt), whose matrices the devkit inverts as they are; its stats.txt
// and per-length plot files printed with %.17g. Its units: translation as a fraction, rotation
// in rad/m. (The float build differs from these by about 1e-5 relative.) The drive's steps are
// not whole metres, so no segment ends on a tie that rounding could flip.
TEST(EvalKitti, MatchesTheDevkitsOwnNumbers) {
  struct Length {
    double length_m;
    int segments;
    double t, r;
  };
  const Length kDevkit[] = {{100, 52, 0.011562242249416653, 0.00014623546413924593},
                            {200, 46, 0.014976100385691657, 0.00014292678673253289},
                            {300, 39, 0.019400495276775138, 0.00014324037918966688},
                            {400, 30, 0.023168745950658591, 0.00014290030410130119},
                            {500, 25, 0.025015711541556369, 0.0001440414694303306},
                            {600, 17, 0.026756032534053297, 0.00014436738640777067},
                            {700, 9, 0.026603186103795386, 0.00014202639512415026},
                            {800, 3, 0.023159392461292772, 0.00014057475288946965}};
  const double kOverallT = 0.018692176936476575, kOverallR = 0.0001439253590762419;
  const fs::path dir = test::temp_dir("eval_kitti");
  test_files::write_kitti_drive(dir);
  ASSERT_EQ(test::run_slamkit("eval kitti " + quoted(dir / "gt.txt") + " " +
                              quoted(dir / "est.txt") + " --quiet --json " +
                              quoted(dir / "metrics.json")),
            0);
  std::ifstream in(dir / "metrics.json");
  const nlohmann::json k = nlohmann::json::parse(in)["kitti"];
  const auto expect_near = [](const nlohmann::json& got, double want, const std::string& what) {
    EXPECT_NEAR(got.get<double>(), want, 1e-9 * std::abs(want)) << what;
  };
  EXPECT_EQ(k["segments"], 221);
  expect_near(k["trans_pct"], 100 * kOverallT, "overall %");
  expect_near(k["rot_deg_per_m"], kOverallR * 180 / M_PI, "overall deg/m");
  ASSERT_EQ(k["lengths"].size(), 8u);
  for (size_t i = 0; i < 8; ++i) {
    const nlohmann::json& l = k["lengths"][i];
    const std::string what = std::to_string(int(kDevkit[i].length_m)) + " m";
    EXPECT_EQ(l["length_m"], kDevkit[i].length_m) << what;
    EXPECT_EQ(l["segments"], kDevkit[i].segments) << what;
    expect_near(l["trans_pct"], 100 * kDevkit[i].t, what + " %");
    expect_near(l["rot_deg_per_m"], kDevkit[i].r * 180 / M_PI, what + " deg/m");
  }
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
