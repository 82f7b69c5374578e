// `slamkit eval` on KITTI and EuRoC files: the same poses in another format print the same
// summary, formats mix, and bad format input exits 2 with one line naming file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

struct Pose {
  double stamp;
  Eigen::Vector3d t;
  Eigen::Quaterniond q;
};

// n poses on a turning helix; `shift` and `wobble` make an estimate differ from groundtruth.
std::vector<Pose> helix(size_t n, const std::function<double(size_t)>& stamp, double wobble) {
  std::vector<Pose> poses;
  for (size_t k = 0; k < n; ++k) {
    const double s = 0.05 * double(k);
    const Eigen::Quaterniond q(
        Eigen::AngleAxisd(0.3 * s + wobble * std::sin(7 * s), Eigen::Vector3d::UnitZ()) *
        Eigen::AngleAxisd(0.1 * std::sin(s), Eigen::Vector3d::UnitX()));
    poses.push_back({stamp(k),
                     Eigen::Vector3d(std::cos(s) + wobble * std::cos(5 * s), std::sin(s),
                                     0.1 * s + wobble * std::sin(3 * s)),
                     q});
  }
  return poses;
}

fs::path write_tum(const fs::path& path, const std::vector<Pose>& poses) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  for (const Pose& p : poses)
    std::fprintf(f, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.stamp, p.t.x(),
                 p.t.y(), p.t.z(), p.q.x(), p.q.y(), p.q.z(), p.q.w());
  std::fclose(f);
  return path;
}

// The poses as KITTI's [R|t] rows; their stamps into `times` unless it is empty.
fs::path write_kitti(const fs::path& path, const std::vector<Pose>& poses,
                     const fs::path& times = {}) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  for (const Pose& p : poses) {
    const Eigen::Matrix3d R = p.q.toRotationMatrix();
    for (int r = 0; r < 3; ++r)
      std::fprintf(f, "%.17g %.17g %.17g %.17g%s", R(r, 0), R(r, 1), R(r, 2), p.t(r),
                   r == 2 ? "\n" : " ");
  }
  std::fclose(f);
  if (!times.empty()) {
    std::ofstream out(times);
    out.precision(17);
    for (const Pose& p : poses) out << p.stamp << "\n";
  }
  return path;
}

// EuRoC's groundtruth layout (17 columns, w-first); stamps are whole seconds here.
fs::path write_euroc(const fs::path& path, const std::vector<Pose>& poses) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  std::fprintf(f,
               "#timestamp, p_RS_R_x [m], p_RS_R_y [m], p_RS_R_z [m], q_RS_w [], q_RS_x [], "
               "q_RS_y [], q_RS_z [], v_x, v_y, v_z, bw_x, bw_y, bw_z, ba_x, ba_y, ba_z\n");
  for (const Pose& p : poses)
    std::fprintf(f, "%lld,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,0,0,0,0,0,0,0,0,0\n",
                 (long long)std::llround(p.stamp) * 1'000'000'000LL, p.t.x(), p.t.y(), p.t.z(),
                 p.q.w(), p.q.x(), p.q.y(), p.q.z());
  std::fclose(f);
  return path;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// The summary printed by `eval all` (stdout only; no files written).
std::string summary(const fs::path& gt, const fs::path& est, const std::string& options = "") {
  const test::SlamkitResult r =
      test::run_slamkit_apart("eval all " + quoted(gt) + " " + quoted(est) + " " + options);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  return r.out;
}

const auto kIndex = [](size_t k) { return double(k); };

TEST(EvalFormats, KittiAndEurocFilesPrintTheSameSummaryAsTheirTumForm) {
  const fs::path dir = test::temp_dir("eval_formats");
  const std::vector<Pose> gt = helix(200, kIndex, 0.0), est = helix(200, kIndex, 0.02);
  const std::string tum = summary(write_tum(dir / "gt.txt", gt), write_tum(dir / "est.txt", est));
  EXPECT_NE(tum.find("absolute_translational_error.rmse"), std::string::npos) << tum;
  // KITTI without times.txt: the pose index is the stamp, as in the TUM files here.
  EXPECT_EQ(summary(write_kitti(dir / "gt_kitti.txt", gt), write_kitti(dir / "est_kitti.txt", est)),
            tum);
  EXPECT_EQ(summary(dir / "gt_kitti.txt", dir / "est_kitti.txt", "--format kitti"), tum);
  EXPECT_EQ(summary(write_euroc(dir / "gt.csv", gt), write_euroc(dir / "est.csv", est)), tum);
  EXPECT_EQ(summary(dir / "gt.csv", dir / "est.csv", "--format euroc"), tum);
}

TEST(EvalFormats, KittiStampsComeFromTimesFile) {
  const fs::path dir = test::temp_dir("eval_formats");
  const auto at_30hz = [](size_t k) { return 1000.0 + double(k) / 30.0; };
  const std::vector<Pose> gt = helix(200, at_30hz, 0.0), est = helix(200, at_30hz, 0.02);
  const std::string tum = summary(write_tum(dir / "gt.txt", gt), write_tum(dir / "est.txt", est));
  write_kitti(dir / "est_kitti.txt", est, dir / "times.txt");
  EXPECT_EQ(summary(dir / "gt.txt", dir / "est_kitti.txt", "--times " + quoted(dir / "times.txt")),
            tum);
  // Without it the stamps are 0..199 s: nothing overlaps the groundtruth's 1000 s.
  std::string log;
  EXPECT_EQ(test::run_slamkit("eval ate " + quoted(dir / "gt.txt") + " " +
                                  quoted(dir / "est_kitti.txt"),
                              &log),
            2);
}

TEST(EvalFormats, MixedPairRecordsEachFormatInMetricsJson) {
  const fs::path dir = test::temp_dir("eval_formats");
  const std::vector<Pose> gt = helix(200, kIndex, 0.0), est = helix(200, kIndex, 0.02);
  const std::string tum = summary(write_tum(dir / "gt.txt", gt), write_tum(dir / "est.txt", est));
  write_euroc(dir / "gt.csv", gt);
  EXPECT_EQ(summary(dir / "gt.csv", dir / "est.txt", "--out " + quoted(dir / "run") + " --no-plot"),
            tum);
  std::ifstream in(dir / "run" / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_EQ(m["inputs"]["groundtruth"]["format"], "euroc");
  EXPECT_EQ(m["inputs"]["estimate"]["format"], "tum");
  // Per-file options win over --format.
  EXPECT_EQ(summary(dir / "gt.csv", dir / "est.txt", "--format tum --gt-format euroc"), tum);
}

TEST(EvalFormats, BadFormatInputExits2WithOneLineNamingFileAndLine) {
  const fs::path dir = test::temp_dir("eval_formats");
  const std::vector<Pose> gt = helix(20, kIndex, 0.0);
  write_tum(dir / "gt.txt", gt);
  write_euroc(dir / "gt.csv", gt);
  const auto fails = [&](const std::string& arguments, const std::string& fragment) {
    const test::SlamkitResult r = test::run_slamkit_apart(arguments);
    EXPECT_EQ(r.code, 2) << arguments;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  };
  const std::string gt_txt = quoted(dir / "gt.txt") + " ";
  std::ofstream(dir / "small.csv") << "5,1,2,3,1,0,0,0\n6,1,2,3,1,0,0,0\n";
  fails("eval all " + gt_txt + quoted(dir / "small.csv"), "small.csv:1: cannot tell the format");
  std::ofstream(dir / "bad.csv") << "#timestamp,x\n1,2,3,4,1,0,0,0\n1.5,2,3,4,1,0,0,0\n";
  fails("eval all " + gt_txt + quoted(dir / "bad.csv"), "bad.csv:3: field 1 is not an integer");
  std::ofstream(dir / "k.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1\n";
  fails("eval ate " + gt_txt + quoted(dir / "k.txt") + " --est-format kitti",
        "k.txt:2: expected 12 fields");
  std::ofstream(dir / "times.txt") << "0\n1\n2\n";
  std::ofstream(dir / "k2.txt") << "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 0 0 1 0 0 0 0 1 0\n";
  fails("eval ate " + gt_txt + quoted(dir / "k2.txt") + " --times " + quoted(dir / "times.txt"),
        "times.txt:3: stamp 3 has no pose");
  // An EuRoC file read as TUM has nanosecond stamps, which the TUM rules refuse as such.
  fails("eval ate " + gt_txt + quoted(dir / "gt.csv") + " --est-format tum", "gt.csv:2: expected 8");
  // An unknown format is a usage error, as any bad option value is.
  const test::SlamkitResult usage = test::run_slamkit_apart("eval ate " + gt_txt + gt_txt +
                                                            "--format csv");
  EXPECT_NE(usage.code, 0);
  EXPECT_NE(usage.err.find("--format: csv not in {tum,kitti,euroc}"), std::string::npos)
      << usage.err;
}

}  // namespace
}  // namespace slamkit::eval
