// The mesh in the report page's data: in the page's frame like the map, its triangles within
// their share of the budget, simplified the same way every time when over it; absent when a run
// has none or the budget is 0.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "eval/report/mesh_simplification.h"
#include "eval/report/report_data.h"
#include "report/mesh_fixtures.h"
#include "support/test_data.h"

namespace slamkit::eval {
namespace {

using nlohmann::json;

const Eigen::Vector3f kCentre(1, 2, 0.5);
constexpr float kRadius = 0.8f;

template <class T>
std::vector<T> decode_array(const json& base64) {
  const std::string bytes = test::base64_decode(base64.get<std::string>());
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

// A run evaluated against groundtruth: the page draws it moved by the alignment, a quarter turn
// about z, a scale of 2 and a shift of (1, 2, 3).
RunFolder aligned_run(const std::string& name) {
  RunFolder run;
  run.name = name;
  run.to_groundtruth.linear() << 0, -2, 0, 2, 0, 0, 0, 0, 2;
  run.to_groundtruth.translation() = Eigen::Vector3d(1, 2, 3);
  return run;
}

json mesh_data(const std::vector<PlyCloud>& meshes, size_t budget) {
  std::vector<RunFolder> runs;
  for (size_t i = 0; i < meshes.size(); ++i) runs.push_back(aligned_run("run" + std::to_string(i)));
  ReportOptions options;
  options.mesh_triangle_budget = budget;
  return report_data(runs, std::vector<PlyCloud>(meshes.size()), meshes, options);
}

// The embedded mesh is `expected` moved into the page's frame: the same triangles and colours,
// each vertex within the 16-bit step of its box.
void expect_embedded(const json& embedded, const PlyCloud& expected,
                     const Eigen::Affine3d& to_page) {
  ASSERT_EQ(embedded["count"], expected.triangles.size());
  const std::vector<uint32_t> indices = decode_array<uint32_t>(embedded["indices"]);
  const std::vector<uint16_t> positions = decode_array<uint16_t>(embedded["positions"]);
  const std::vector<uint8_t> colours = decode_array<uint8_t>(embedded["colours"]);
  ASSERT_EQ(indices.size(), 3 * expected.triangles.size());
  ASSERT_EQ(positions.size(), 3 * expected.points.size());
  ASSERT_EQ(colours.size(), 3 * expected.points.size());
  for (size_t t = 0; t < expected.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(indices[3 * t + k], expected.triangles[t][k]);
  for (size_t i = 0; i < expected.points.size(); ++i) {
    const Eigen::Vector3d original = to_page * expected.points[i].cast<double>();
    for (int d = 0; d < 3; ++d) {
      const double step = embedded["size"][d].get<double>() / 65535;
      const double position = embedded["min"][d].get<double>() + positions[3 * i + d] * step;
      ASSERT_NEAR(position, original[d], step) << i << " " << d;
      ASSERT_EQ(colours[3 * i + d], expected.colours[i][d]) << i;
    }
  }
}

TEST(ReportMesh, AMeshWithinTheBudgetIsEmbeddedWholeInThePagesFrame) {
  const PlyCloud sphere = test::sphere_mesh(40, 80, kCentre, kRadius);
  const json data = mesh_data({sphere}, 300'000);
  EXPECT_EQ(data["mesh_triangle_budget"], 300'000);
  const json& mesh = data["runs"][0]["mesh"];
  EXPECT_EQ(mesh["total"], sphere.triangles.size());
  expect_embedded(mesh, sphere, aligned_run("").to_groundtruth);
}

TEST(ReportMesh, AMeshOverTheBudgetIsSimplifiedBelowItTheSameWayEachTime) {
  const PlyCloud sphere = test::sphere_mesh(300, 600, kCentre, kRadius);
  const json data = mesh_data({sphere}, 20'000);
  const json& mesh = data["runs"][0]["mesh"];
  EXPECT_EQ(mesh["total"], sphere.triangles.size());
  EXPECT_LE(mesh["count"].get<size_t>(), 20'000u);
  expect_embedded(mesh, simplify_mesh(sphere, 20'000), aligned_run("").to_groundtruth);
  EXPECT_EQ(mesh_data({sphere}, 20'000), data);
}

TEST(ReportMesh, RunsShareTheBudgetAndARunWithoutAMeshOrABudgetOfZeroHasNone) {
  const PlyCloud sphere = test::sphere_mesh(100, 200, kCentre, kRadius);  // 39,600 triangles
  const json data = mesh_data({sphere, PlyCloud{}, sphere}, 30'000);
  EXPECT_LE(data["runs"][0]["mesh"]["count"].get<size_t>(), 15'000u);
  EXPECT_FALSE(data["runs"][1].contains("mesh"));
  EXPECT_EQ(data["runs"][2]["mesh"], data["runs"][0]["mesh"]);
  EXPECT_FALSE(mesh_data({sphere}, 0)["runs"][0].contains("mesh"));
}

}  // namespace
}  // namespace slamkit::eval
