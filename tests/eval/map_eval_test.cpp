// What map-eval judges in a PLY map: the mesh sampler (coverage, plane, spacing, determinism),
// the map's points read and checked (refusals naming the file), and the numbers: the same
// points as double or float give the same map quality, and a mesh on the true surface is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <unordered_map>

#include "core/error.h"
#include "datasets/synth/map_quality.h"
#include "datasets/synth/sequence_writer.h"
#include "datasets/synth/trajectory_presets.h"
#include "eval/run/map_points.h"
#include "eval/run/mesh_sampling.h"
#include "fusion/ply_cloud.h"
#include "support/test_data.h"
#include "surface_maps.h"
#include "synth/shared_room.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

// Nearest-sample distances, searched in the buckets of a grid around the query.
class Samples {
 public:
  Samples(const std::vector<Eigen::Vector3f>& points, double cell) : cell_(cell) {
    for (const Eigen::Vector3f& p : points) buckets_[cell_key(cell_of(p))].push_back(p);
  }
  double nearest(const Eigen::Vector3f& q, const Eigen::Vector3f* skip = nullptr) const {
    double best = 1e9;
    const Eigen::Vector3i c = cell_of(q);
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dz = -2; dz <= 2; ++dz) {
          const auto it = buckets_.find(cell_key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == buckets_.end()) continue;
          for (const Eigen::Vector3f& p : it->second)
            if (skip == nullptr || p != *skip) best = std::min(best, double((p - q).norm()));
        }
    return best;
  }

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3f& p) const {
    return (p.cast<double>() / cell_).array().floor().cast<int>();
  }
  static int64_t cell_key(const Eigen::Vector3i& c) {
    return (int64_t(c.x()) + 1000) * 4000000 + (int64_t(c.y()) + 1000) * 2000 + c.z() + 1000;
  }
  double cell_;
  std::unordered_map<int64_t, std::vector<Eigen::Vector3f>> buckets_;
};

const std::vector<Eigen::Vector3f> kSquare = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<Triangle> kSquareTriangles = {{0, 1, 2}, {0, 2, 3}};

TEST(MeshSampling, AUnitSquareIsCoveredInItsPlaneWithSamplesAtMostTheSpacingApart) {
  constexpr double kSpacing = 0.05;
  std::vector<Eigen::Vector3f> vertices = kSquare;
  vertices.emplace_back(5, 5, 5);  // used by no triangle: left out
  const std::vector<Eigen::Vector3f> samples =
      sample_mesh_surface(vertices, kSquareTriangles, kSpacing);
  EXPECT_EQ(mesh_sample_count(vertices, kSquareTriangles, kSpacing, 1000000), samples.size());
  // Area-proportional: about one sample per spacing^2 (400), plus the rows' ends.
  EXPECT_GT(samples.size(), 400u);
  EXPECT_LT(samples.size(), 600u);
  for (const Eigen::Vector3f& p : samples) {
    EXPECT_EQ(p.z(), 0.0f);
    EXPECT_TRUE(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1) << p.transpose();
  }
  for (size_t i = 0; i < 4; ++i)
    EXPECT_EQ(std::count(samples.begin(), samples.end(), kSquare[i]), 1) << i;

  const Samples index(samples, kSpacing);
  double farthest_neighbour = 0, farthest_point = 0;
  for (const Eigen::Vector3f& p : samples)
    farthest_neighbour = std::max(farthest_neighbour, index.nearest(p, &p));
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j)
      farthest_point = std::max(farthest_point, index.nearest(Eigen::Vector3f(i, j, 0) / 200));
  EXPECT_LE(farthest_neighbour, kSpacing * 1.0001);
  EXPECT_LE(farthest_point, 1.12 * kSpacing);

  EXPECT_EQ(sample_mesh_surface(vertices, kSquareTriangles, kSpacing), samples);  // deterministic
  // Four times the area, about four times the samples (less the rows' ends, fewer at a finer
  // spacing).
  std::vector<Eigen::Vector3f> twice;
  for (const Eigen::Vector3f& v : kSquare) twice.push_back(2 * v);
  const double ratio = double(sample_mesh_surface(twice, kSquareTriangles, kSpacing / 5).size()) /
                       double(sample_mesh_surface(kSquare, kSquareTriangles, kSpacing / 5).size());
  EXPECT_NEAR(ratio, 4.0, 0.2);
}

TEST(MeshSampling, SliversAndDegenerateTrianglesAndHugeOnes) {
  constexpr double kSpacing = 0.0025;
  // A sliver 1 m long, 0.1 mm wide: samples along it, not a square grid of its length.
  const std::vector<Eigen::Vector3f> sliver = {{0, 0, 0}, {1, 0, 0}, {0.3f, 1e-4f, 0}};
  const std::vector<Eigen::Vector3f> samples = sample_mesh_surface(sliver, {{0, 1, 2}}, kSpacing);
  EXPECT_GE(samples.size(), 400u);
  EXPECT_LE(samples.size(), 1300u);
  // All three corners at one place: the vertex alone.
  const std::vector<Eigen::Vector3f> point = {{1, 2, 3}};
  EXPECT_EQ(sample_mesh_surface(point, {{0, 0, 0}}, kSpacing), point);
  // A triangle of a thousand kilometres: counted, not sampled, and the count stops early.
  const std::vector<Eigen::Vector3f> huge = {{0, 0, 0}, {1e6f, 0, 0}, {0, 1e6f, 0}};
  EXPECT_EQ(mesh_sample_count(huge, {{0, 1, 2}}, kSpacing, 1000), 1001u);
}

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string error_of(const fs::path& file) {
  try {
    read_map_points(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MapPoints, ACloudIsItsPointsAndAMeshItsSurfaceWithoutUnusedVertices) {
  const fs::path dir = test::temp_dir("map_points");
  PlyCloud cloud;
  cloud.points = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  cloud.colours.assign(3, {0, 0, 0});
  write_ply_cloud(dir / "cloud.ply", cloud);
  const MapPoints from_cloud = read_map_points(dir / "cloud.ply");
  EXPECT_EQ(from_cloud.points, cloud.points);
  EXPECT_EQ(from_cloud.mesh_triangles, 0u);

  PlyCloud mesh;
  mesh.points = kSquare;
  // Vertices no face uses: far away, and not even finite.
  mesh.points.emplace_back(50, 50, 50);
  mesh.points.emplace_back(std::numeric_limits<float>::quiet_NaN(), 0, 0);
  mesh.colours.assign(mesh.points.size(), {0, 0, 0});
  mesh.triangles = kSquareTriangles;
  write_ply_cloud(dir / "mesh.ply", mesh);
  const MapPoints from_mesh = read_map_points(dir / "mesh.ply");
  EXPECT_EQ(from_mesh.mesh_triangles, 2u);
  EXPECT_EQ(from_mesh.points, sample_mesh_surface(kSquare, kSquareTriangles, kMeshSampleSpacing));
}

TEST(MapPoints, MapsThatWouldGiveMeaninglessNumbersAreRefusedNamingTheFile) {
  const fs::path dir = test::temp_dir("map_points_bad");
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\n";
  const struct {
    const char* name;
    std::string text;
    const char* reason;
  } cases[] = {
      {"nan.ply", header + "end_header\n0 0 1\n1 0 1\n0 nan 1\n", "vertex 2 is not finite"},
      {"inf.ply", header + "end_header\n0 0 1\n-inf 0 1\n0 1 1\n", "vertex 1 is not finite"},
      // What PCL's loader made of Open3D's double coordinates.
      {"origin.ply", header + "end_header\n0 0 0\n0 0 0\n0 0 0\n",
       "all 3 points of the map are at (0, 0, 0)"},
      {"empty.ply",
       "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n",
       "no point to judge"},
      {"flat_mesh.ply",
       header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                "1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n",
       "all 3 points of the map are at (1, 1, 1)"},
      {"huge_mesh.ply",
       header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                "0 0 0\n1000000 0 0\n0 1000000 0\n3 0 1 2\n",
       "too large for map-eval"},
  };
  for (const auto& c : cases) {
    write_file(dir / c.name, c.text);
    const std::string message = error_of(dir / c.name);
    EXPECT_EQ(message.rfind((dir / c.name).string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.reason), std::string::npos) << message;
  }
}

// The numbers, on the desk scene as tests/fusion/map_quality_test.cpp judges it.
const std::vector<Eigen::Isometry3d>& poses() {
  static const std::vector<Eigen::Isometry3d> p =
      synth::make_trajectory(synth::Preset::kDesk, 30, 1);
  return p;
}

synth::MapQuality evaluate(const std::vector<Eigen::Vector3f>& map) {
  return synth::evaluate_map_quality(map, synth::test::shared_room(), poses(),
                                     synth::synthetic_camera());
}

test::SurfaceGrid surface_grid(int stride) {
  return test::surface_grid(synth::test::shared_room(), synth::synthetic_camera(), poses()[0],
                            stride);
}

TEST(MapEval, TheSamePointsAsDoubleOrFloatGiveTheSameNumbers) {
  const fs::path dir = test::temp_dir("map_eval_double");
  const std::vector<synth::SurfaceHit> hits = test::hits_of(surface_grid(2));
  test::write_open3d_like_ply(dir / "double.ply", hits);
  test::write_float_ply(dir / "float.ply", hits);

  const synth::MapQuality a = evaluate(read_map_points(dir / "double.ply").points);
  const synth::MapQuality b = evaluate(read_map_points(dir / "float.ply").points);
  EXPECT_EQ(a.map_points, hits.size());
  EXPECT_EQ(b.map_points, hits.size());
  EXPECT_EQ(a.accuracy_mean, b.accuracy_mean);
  EXPECT_EQ(a.accuracy_median, b.accuracy_median);
  EXPECT_EQ(a.accuracy_p95, b.accuracy_p95);
  EXPECT_EQ(a.accuracy_max, b.accuracy_max);
  EXPECT_EQ(a.covered_samples, b.covered_samples);
  EXPECT_EQ(a.surface_samples, b.surface_samples);
  // And they are the true surface's, not the origin's.
  EXPECT_LT(a.accuracy_max, 1e-5);
  EXPECT_GT(a.completeness, 0.3);
}

TEST(MapEval, AMeshOnTheTrueSurfaceIsExactAndCoversMoreThanItsVertices) {
  const fs::path dir = test::temp_dir("map_eval_mesh");
  // Every 32nd pixel: vertices 6 cm or more apart, beyond the 2 cm completeness radius.
  const PlyCloud mesh = test::mesh_on_surface(surface_grid(32));
  ASSERT_GT(mesh.triangles.size(), 100u);
  write_ply_cloud(dir / "mesh.ply", mesh);

  const MapPoints map = read_map_points(dir / "mesh.ply");
  EXPECT_EQ(map.mesh_triangles, mesh.triangles.size());
  const synth::MapQuality of_mesh = evaluate(map.points);
  const synth::MapQuality of_vertices = evaluate(mesh.points);
  EXPECT_GT(of_mesh.map_points, 50 * mesh.points.size());
  EXPECT_LT(of_mesh.accuracy_max, 1e-5);  // float rounding only
  // 0.45 against 0.12: the samples fill the gaps between the vertices.
  EXPECT_GT(of_mesh.completeness, 3 * of_vertices.completeness);
}

}  // namespace
}  // namespace slamkit::eval
