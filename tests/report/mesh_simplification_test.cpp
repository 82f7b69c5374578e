// The mesh the report page embeds when mesh.ply has more triangles than its budget: below the
// budget, on the surface, in the surface's colours, each triangle once, the same every time.
#include "eval/report/mesh_simplification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "report/mesh_fixtures.h"

namespace slamkit::eval {
namespace {

const Eigen::Vector3f kCentre(1, 2, 0.5);
constexpr float kRadius = 0.8f;

// Every index in range, no triangle with a repeated vertex, no set of three vertices twice,
// every vertex used.
void expect_a_clean_mesh(const PlyCloud& mesh) {
  ASSERT_EQ(mesh.colours.size(), mesh.points.size());
  std::set<std::array<uint32_t, 3>> seen;
  std::vector<bool> used(mesh.points.size(), false);
  for (std::array<uint32_t, 3> t : mesh.triangles) {
    for (uint32_t v : t) {
      ASSERT_LT(v, mesh.points.size());
      used[v] = true;
    }
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    std::sort(t.begin(), t.end());
    EXPECT_TRUE(seen.insert(t).second) << "a triangle twice";
  }
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

TEST(MeshSimplification, AMeshWithinTheBudgetComesBackAsItIs) {
  const PlyCloud sphere = test::sphere_mesh(20, 40, kCentre, kRadius);
  const PlyCloud same = simplify_mesh(sphere, sphere.triangles.size());
  EXPECT_EQ(same.triangles, sphere.triangles);
  EXPECT_EQ(same.points, sphere.points);
  EXPECT_EQ(same.colours, sphere.colours);
  EXPECT_TRUE(simplify_mesh(sphere, 0).triangles.empty());
}

TEST(MeshSimplification, AMeshOverTheBudgetIsClusteredBelowItOnItsSurfaceInItsColours) {
  const PlyCloud sphere = test::sphere_mesh(300, 600, kCentre, kRadius);
  ASSERT_EQ(sphere.triangles.size(), 358'800u);
  constexpr size_t kBudget = 30'000;
  const PlyCloud simple = simplify_mesh(sphere, kBudget);
  EXPECT_LE(simple.triangles.size(), kBudget);
  // The grid is coarsened no more than needed: most of the budget is used.
  EXPECT_GE(simple.triangles.size(), kBudget / 2);
  expect_a_clean_mesh(simple);
  EXPECT_TRUE(simple.normals.empty());
  for (size_t i = 0; i < simple.points.size(); ++i) {
    // A mean of points on the sphere lies just inside it, by a fraction of the cell (~2 cm).
    const float distance = (simple.points[i] - kCentre).norm();
    EXPECT_LT(distance, kRadius + 1e-4f);
    EXPECT_GT(distance, kRadius - 0.01f);
    // The colour is linear in position: the mean colour is the colour at the mean position,
    // but for rounding.
    const Rgb8 expected = test::colour_by_position(simple.points[i], kCentre, kRadius);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(simple.colours[i][d], expected[d], 2) << i;
  }
}

TEST(MeshSimplification, TheSameMeshAndBudgetGiveTheSameMesh) {
  const PlyCloud sphere = test::sphere_mesh(200, 400, kCentre, kRadius);
  const PlyCloud a = simplify_mesh(sphere, 12'345), b = simplify_mesh(sphere, 12'345);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.colours, b.colours);
}

// A plate 0.5 mm thick, its two sides facing away from each other, as a TSDF meshes a thin board.
PlyCloud thin_plate(int cells) {
  PlyCloud mesh;
  for (float z : {0.0f, 0.0005f}) {
    const uint32_t first = uint32_t(mesh.points.size());
    for (int y = 0; y <= cells; ++y)
      for (int x = 0; x <= cells; ++x) {
        mesh.points.emplace_back(float(x) / cells, float(y) / cells, z);
        mesh.colours.push_back({200, 100, 50});
      }
    const auto at = [&](int x, int y) { return first + uint32_t(y * (cells + 1) + x); };
    const bool top = z > 0;  // counter-clockwise seen from +z; the bottom side from -z
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x) {
        const uint32_t a = at(x, y), b = at(x + 1, y), c = at(x + 1, y + 1), d = at(x, y + 1);
        mesh.triangles.push_back(top ? std::array{a, b, c} : std::array{a, c, b});
        mesh.triangles.push_back(top ? std::array{a, c, d} : std::array{a, d, c});
      }
  }
  return mesh;
}

TEST(MeshSimplification, APartThinnerThanACellBecomesOneLayerFacingOneWay) {
  const PlyCloud plate = thin_plate(200);
  const PlyCloud simple = simplify_mesh(plate, 10'000);
  EXPECT_LE(simple.triangles.size(), 10'000u);
  EXPECT_GE(simple.triangles.size(), 2'000u);
  expect_a_clean_mesh(simple);  // the two sides merged into one
  for (const Eigen::Vector3f& p : simple.points) EXPECT_NEAR(p.z(), 0.00025f, 0.00026f);
  // The side that comes first in the mesh (the bottom) is kept: no opposite windings over the
  // same vertices, whose normals would cancel.
  for (const std::array<uint32_t, 3>& t : simple.triangles) {
    const Eigen::Vector3f& a = simple.points[t[0]];
    EXPECT_LT((simple.points[t[1]] - a).cross(simple.points[t[2]] - a).z(), 0);
  }
}

}  // namespace
}  // namespace slamkit::eval
