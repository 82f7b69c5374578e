// The report page's data: what it embeds from a run folder, in which frame, within the point
// budget; what it says when files are missing; what it refuses.
#include "eval/report/report_page.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "eval/report/base64.h"
#include "eval/report/report_assets.h"
#include "io/trajectory_io.h"
#include "report/mesh_fixtures.h"
#include "support/test_data.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void write_text(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// A run folder as `slamkit run` leaves it, without groundtruth: a straight 2 m path along x.
fs::path make_run_folder(const std::string& tag, int frames = 20) {
  const fs::path dir = test::temp_dir(tag);
  Trajectory trajectory, keyframes;
  std::string tracking =
      "index,stamp,solver,features,matches,pairs_3d,inliers,refined,lost,failure,keyframe,"
      "similarity,reference_keyframe,decode_ms,features_ms\n";
  for (int i = 0; i < frames; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.1 * i, 0, 0);
    const double stamp = 100 + 0.1 * i;
    const bool lost = i == 5;
    if (!lost) trajectory.push_back(stamp, pose);
    if (i % 5 == 0) keyframes.push_back(stamp, pose);
    tracking += std::to_string(i) + "," + std::to_string(stamp) +
                ",svd_ransac,1000,600,500,450,1," + (lost ? "1,too few inliers," : "0,,") +
                (i % 5 == 0 ? "1" : "0") + ",0.5,0,3.5,9\n";
  }
  write_tum_trajectory(dir / "trajectory.txt", trajectory);
  write_tum_trajectory(dir / "keyframes.txt", keyframes);
  write_text(dir / "tracking.csv", tracking);
  write_text(dir / "run.json",
             R"({"status": "complete", "version": "test", "seconds": {"total": 2.5}})");
  write_text(dir / "settings.yaml", "orb:\n  num_features: 1000\n");
  return dir;
}

// The JSON a page embeds, read back as the page's script reads it.
json embedded_data(const fs::path& page) {
  const std::string html = test::read_text(page);
  const std::string open = R"(<script type="application/json" id="report-data">)";
  const size_t begin = html.find(open) + open.size();
  std::string text = html.substr(begin, html.find("</script>", begin) - begin);
  for (size_t at = text.find("<\\/"); at != std::string::npos; at = text.find("<\\/", at))
    text.erase(at + 1, 1);
  return json::parse(text);
}

std::vector<uint8_t> decode_base64(const std::string& text) {
  const std::string bytes = test::base64_decode(text);
  return std::vector<uint8_t>(bytes.begin(), bytes.end());
}

template <class T>
std::vector<T> decode_array(const std::string& text) {
  const std::vector<uint8_t> bytes = decode_base64(text);
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

TEST(ReportPage, Base64MatchesTheRfc4648Vectors) {
  const std::pair<const char*, const char*> vectors[] = {{"", ""},
                                                         {"f", "Zg=="},
                                                         {"fo", "Zm8="},
                                                         {"foo", "Zm9v"},
                                                         {"foob", "Zm9vYg=="},
                                                         {"fooba", "Zm9vYmE="},
                                                         {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors)
    EXPECT_EQ(base64_encode(plain, std::strlen(plain)), encoded) << plain;
}

TEST(ReportPage, TheStridedSubsetTakesEachPointOnceOverTheWholeMap) {
  const std::vector<size_t> subset = strided_subset(1000, 300);
  ASSERT_EQ(subset.size(), 300u);
  EXPECT_EQ(subset.front(), 0u);
  EXPECT_GE(subset.back(), 996u);  // the last stride reaches the end
  for (size_t k = 1; k < subset.size(); ++k) EXPECT_GT(subset[k], subset[k - 1]);
  EXPECT_EQ(strided_subset(10, 300).size(), 10u);  // a map within the budget goes whole
}

TEST(ReportPage, AMapOfTwoMillionPointsIsCutToTheBudgetAndKeepsItsPositions) {
  const fs::path dir = make_run_folder("report_budget");
  PlyCloud cloud;
  constexpr size_t kPoints = 2'000'000;
  for (size_t i = 0; i < kPoints; ++i) {
    cloud.points.emplace_back(float(i % 1000) * 0.004f, float(i / 1000 % 1000) * 0.003f,
                              float(i % 7) * 0.5f);
    cloud.colours.push_back({uint8_t(i), uint8_t(i >> 8), 7});
  }
  write_ply_cloud(dir / "map.ply", cloud);
  ReportOptions options;
  options.point_budget = 300'000;
  const ReportSummary summary = write_report({dir}, dir / "report.html", options);
  EXPECT_EQ(summary.map_points, kPoints);
  EXPECT_EQ(summary.map_points_shown, 300'000u);
  EXPECT_LT(summary.bytes, 15'000'000u);

  const json map = embedded_data(dir / "report.html")["runs"][0]["map"];
  EXPECT_EQ(map["total"], kPoints);
  ASSERT_EQ(map["count"], 300'000);
  const std::vector<uint16_t> quantised = decode_array<uint16_t>(map["positions"]);
  const std::vector<uint8_t> colours = decode_base64(map["colours"]);
  ASSERT_EQ(quantised.size(), 3 * 300'000u);
  ASSERT_EQ(colours.size(), 3 * 300'000u);
  // Each embedded point is the map's point at its stride, to within the 16-bit step.
  const std::vector<size_t> kept = strided_subset(kPoints, 300'000);
  for (size_t k : {size_t(0), size_t(12'345), size_t(299'999)}) {
    for (int d = 0; d < 3; ++d) {
      const double step = map["size"][d].get<double>() / 65535;
      const double position = map["min"][d].get<double>() + quantised[3 * k + d] * step;
      EXPECT_NEAR(position, cloud.points[kept[k]][d], step) << k << " " << d;
      EXPECT_EQ(colours[3 * k + d], cloud.colours[kept[k]][d]);
    }
  }
}

TEST(ReportPage, AMeshPlyBesideTheMapIsShownWithinTheTriangleBudget) {
  const fs::path dir = make_run_folder("report_mesh");
  const PlyCloud sphere = test::sphere_mesh(100, 200, Eigen::Vector3f(0, 0, 1), 0.5f);
  write_ply_cloud(dir / "mesh.ply", sphere);
  ReportOptions options;
  options.mesh_triangle_budget = 10'000;
  const ReportSummary summary = write_report({dir}, dir / "report.html", options);
  EXPECT_EQ(summary.mesh_triangles, sphere.triangles.size());
  EXPECT_LE(summary.mesh_triangles_shown, 10'000u);
  const json mesh = embedded_data(dir / "report.html")["runs"][0]["mesh"];
  EXPECT_EQ(mesh["total"], sphere.triangles.size());
  EXPECT_EQ(mesh["count"], summary.mesh_triangles_shown);

  options.mesh_triangle_budget = 0;  // no mesh in the page, and the file is not read
  const ReportSummary without = write_report({dir}, dir / "report.html", options);
  EXPECT_EQ(without.mesh_triangles, 0u);
  EXPECT_FALSE(embedded_data(dir / "report.html")["runs"][0].contains("mesh"));
}

TEST(ReportPage, ARunWithoutMapOrGroundtruthGetsTheTrajectoryAndDiagnosticsAndSaysWhatIsMissing) {
  const fs::path dir = make_run_folder("report_plain");
  const ReportSummary summary = write_report({dir}, dir / "report.html", ReportOptions{});
  const auto says = [&](const std::string& text) {
    return std::any_of(summary.notes.begin(), summary.notes.end(), [&](const std::string& note) {
      return note.find(text) != std::string::npos;
    });
  };
  EXPECT_TRUE(says("no map.ply"));
  EXPECT_TRUE(says("no metrics.json"));
  EXPECT_FALSE(says("mesh.ply"));  // few runs make one: its absence is no news
  const json run = embedded_data(dir / "report.html")["runs"][0];
  EXPECT_FALSE(run.contains("map"));
  EXPECT_FALSE(run.contains("mesh"));
  EXPECT_FALSE(run.contains("groundtruth"));
  EXPECT_EQ(run["frame"], "estimate");
  EXPECT_EQ(run["trajectory"]["count"], 19);  // the lost frame is not in trajectory.txt
  EXPECT_EQ(run["lost"]["count"], 1);
  // The lost frame (stamp 100.5) is drawn at the last pose before it, x = 0.4.
  EXPECT_FLOAT_EQ(decode_array<float>(run["lost"]["positions"])[0], 0.4f);
  EXPECT_EQ(run["keyframes"]["count"], 4);
  const std::vector<float> features = decode_array<float>(run["frames"]["features"]);
  ASSERT_EQ(features.size(), 20u);
  EXPECT_EQ(features[3], 1000);
  const std::vector<float> seconds = decode_array<float>(run["frames"]["seconds"]);
  EXPECT_NEAR(seconds[19], 1.9, 1e-5);             // from the first frame
  EXPECT_FALSE(run["frames"].contains("solver"));  // words, not a numeric series
}

TEST(ReportPage, ARunEvaluatedAgainstGroundtruthIsDrawnInTheGroundtruthsFrame) {
  const fs::path dir = make_run_folder("report_aligned");
  // The alignment of metrics.json: a quarter turn about z, then (1, 2, 3).
  write_text(dir / "metrics.json", R"({"ate": {"rmse": 0.01, "alignment": {"scale": 1,
      "rotation": [[0, -1, 0], [1, 0, 0], [0, 0, 1]], "translation": [1, 2, 3]}}})");
  write_text(dir / "errors.csv",
             "time,ate_m,est_tx,est_ty,est_tz,gt_tx,gt_ty,gt_tz,rot_deg\n"
             "100,0.002,1,2,3,1.001,2,3,0.1\n100.1,0.004,1,2.1,3,1,2.1,3.004,0.1\n");
  write_text(dir / "loop_check.csv",
             "keyframe_stamp,loop_stamp,verdict,error_m,error_deg\n101.5,100,false,0.4,3\n");
  write_report({dir}, dir / "report.html", ReportOptions{});
  const json run = embedded_data(dir / "report.html")["runs"][0];
  EXPECT_EQ(run["frame"], "groundtruth");
  const std::vector<float> positions = decode_array<float>(run["trajectory"]["positions"]);
  // Frame 2 at (0.2, 0, 0) turns to (0, 0.2, 0) and moves by (1, 2, 3).
  EXPECT_NEAR(positions[6], 1.0, 1e-6);
  EXPECT_NEAR(positions[7], 2.2, 1e-6);
  EXPECT_NEAR(positions[8], 3.0, 1e-6);
  const std::vector<float> ate = decode_array<float>(run["trajectory"]["ate"]);
  EXPECT_FLOAT_EQ(ate[1], 0.004f);
  EXPECT_TRUE(std::isnan(ate[2]));  // no groundtruth at that stamp
  ASSERT_EQ(run["loops"].size(), 1u);
  EXPECT_EQ(run["loops"][0]["verdict"], "false");
  EXPECT_NEAR(run["loops"][0]["from"][1].get<double>(), 2 + 1.5, 1e-9);  // keyframe at x 1.5
}

TEST(ReportPage, AnUnfinishedRunGetsAPageWithWhatItsFolderHolds) {
  const fs::path dir = make_run_folder("report_running");
  write_text(dir / "run.json", R"({"status": "interrupted"})");
  const ReportSummary summary = write_report({dir}, dir / "report.html", ReportOptions{});
  ASSERT_FALSE(summary.notes.empty());
  EXPECT_NE(summary.notes.front().find("not complete (run.json says 'interrupted'"),
            std::string::npos);
  EXPECT_EQ(embedded_data(dir / "report.html")["runs"][0]["status"], "interrupted");
}

TEST(ReportPage, SeveralRunsShareTheBudgetOnOnePage) {
  const fs::path a = make_run_folder("report_compare_a"), b = make_run_folder("report_compare_b");
  PlyCloud cloud;
  for (int i = 0; i < 1000; ++i) {
    cloud.points.emplace_back(float(i), 0, 0);
    cloud.colours.push_back({1, 2, 3});
  }
  write_ply_cloud(a / "map.ply", cloud);
  write_ply_cloud(b / "map.ply", cloud);
  ReportOptions options;
  options.point_budget = 600;
  const fs::path page = test::temp_dir("report_compare") / "compare.html";
  EXPECT_EQ(write_report({a, b}, page, options).map_points_shown, 600u);
  const json data = embedded_data(page);
  ASSERT_EQ(data["runs"].size(), 2u);
  EXPECT_EQ(data["runs"][1]["map"]["count"], 300);
}

TEST(ReportPage, ThePageCarriesItsScriptsAndFetchesNothing) {
  const fs::path dir = make_run_folder("report_offline");
  write_report({dir}, dir / "report.html", ReportOptions{});
  const std::string html = test::read_text(dir / "report.html");
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_NE(html.find("default-src 'none'"), std::string::npos);
  EXPECT_NE(html.find("OrbitControls"), std::string::npos);
  EXPECT_NE(html.find("WebGLRenderer"), std::string::npos);
}

// three.js is MIT-licenced: every copy must carry its copyright and permission notice, so the
// page holds them in the very script element of the inlined code, just before it.
TEST(ReportPage, ThePageCarriesThreeJsCopyrightAndLicenceBeforeItsCode) {
  const fs::path dir = make_run_folder("report_licence");
  write_report({dir}, dir / "report.html", ReportOptions{});
  const std::string html = test::read_text(dir / "report.html");
  const size_t notice = html.find("/*! three.js r111");
  ASSERT_NE(notice, std::string::npos);
  const size_t code = html.find(report_assets::three_js.substr(0, 100), notice);
  ASSERT_NE(code, std::string::npos);
  const std::string between = html.substr(notice, code - notice);
  EXPECT_EQ(between.find("</script"), std::string::npos);
  EXPECT_NE(between.find("Copyright © 2010-2017 three.js authors"), std::string::npos);
  EXPECT_NE(between.find("MIT licence"), std::string::npos);
  EXPECT_NE(between.find("Permission is hereby granted, free of charge"), std::string::npos);
  EXPECT_NE(between.find("The above copyright notice and this permission notice shall be"),
            std::string::npos);
  EXPECT_NE(between.find("THE SOFTWARE IS PROVIDED \"AS IS\", WITHOUT WARRANTY OF ANY KIND"),
            std::string::npos);
  EXPECT_NE(between.find("OrbitControls"), std::string::npos);
  EXPECT_NE(between.find("*/"), std::string::npos);  // the comment ends before the code
}

TEST(ReportPage, RefusesWhatIsNotARunFolderAndMalformedFilesWithFileAndLine) {
  const fs::path empty = test::temp_dir("report_empty");
  const fs::path out = empty / "report.html";
  try {
    write_report({empty}, out, ReportOptions{});
    FAIL() << "an empty folder made a page";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a run folder"), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_report({empty / "missing"}, out, ReportOptions{}), InputError);
  const fs::path bad = make_run_folder("report_bad_csv");
  write_text(bad / "tracking.csv", "index,stamp,lost\n0,100,0\n1,abc,0\n");
  try {
    write_report({bad}, out, ReportOptions{});
    FAIL() << "a malformed tracking.csv made a page";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tracking.csv:3:"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace slamkit::eval
