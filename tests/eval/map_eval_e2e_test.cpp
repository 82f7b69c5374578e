// `slamkit map-eval` end to end on the smallest synthetic sequence: a map written with double
// coordinates (as Open3D writes) and with float ones gives the same numbers, and a mesh is
// judged by samples of its surface, saying so.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "datasets/synth/map_quality.h"
#include "io/tum_sequence.h"
#include "support/synthetic_sequence.h"
#include "support/test_data.h"
#include "surface_maps.h"

namespace slamkit::eval {
namespace {

namespace fs = std::filesystem;

struct MapEvalRun {
  test::SlamkitResult result;
  nlohmann::json map;  // the --json file's "map", without the map's "file" name
};

MapEvalRun map_eval(const fs::path& map, const fs::path& sequence) {
  const fs::path json = map.string() + ".json";
  MapEvalRun run;
  run.result = test::run_slamkit_apart("map-eval '" + map.string() + "' '" + sequence.string() +
                                       "' --json '" + json.string() + "'");
  EXPECT_EQ(run.result.code, 0) << run.result.err;
  if (run.result.code == 0) {
    run.map = nlohmann::json::parse(std::ifstream(json))["map"];
    run.map.erase("file");
  }
  return run;
}

// The lines after the first, which names the map's file.
std::string numbers_of(const std::string& out) { return out.substr(out.find('\n') + 1); }

// The synthetic scene of the sequence, seen from its first groundtruth pose.
test::SurfaceGrid surface_grid(const fs::path& folder, int stride) {
  const TumSequence sequence = TumSequence::open(folder);
  const Trajectory& groundtruth = *sequence.groundtruth();
  const Eigen::Isometry3d pose = groundtruth[*groundtruth.nearest(sequence.stamp(0), 0.02)].T_w_c;
  const synth::SyntheticScene scene = synth::make_scene(*synth::read_synthetic_info(folder));
  return test::surface_grid(scene, sequence.camera(), pose, stride);
}

TEST(MapEvalCli, DoubleAndFloatCoordinatesGiveTheSameNumbers) {
  const fs::path sequence = test::synthetic_sequence(synth::Preset::kDesk, 10);
  const fs::path dir = test::temp_dir("map_eval_cli");
  const std::vector<synth::SurfaceHit> hits = test::hits_of(surface_grid(sequence, 4));
  test::write_open3d_like_ply(dir / "double.ply", hits);
  test::write_float_ply(dir / "float.ply", hits);

  const MapEvalRun as_double = map_eval(dir / "double.ply", sequence);
  const MapEvalRun as_float = map_eval(dir / "float.ply", sequence);
  std::printf("%s", as_double.result.out.c_str());
  EXPECT_EQ(numbers_of(as_double.result.out), numbers_of(as_float.result.out));
  EXPECT_EQ(as_double.map, as_float.map);
  EXPECT_EQ(as_double.map["points"], hits.size());
  EXPECT_LT(as_double.map["accuracy"]["max"].get<double>(), 1e-5);
  EXPECT_GT(as_double.map["completeness"].get<double>(), 0.5);
  EXPECT_FALSE(as_double.map.contains("mesh_triangles"));
}

TEST(MapEvalCli, AMeshIsJudgedBySamplesOfItsSurface) {
  const fs::path sequence = test::synthetic_sequence(synth::Preset::kDesk, 10);
  const fs::path dir = test::temp_dir("map_eval_cli_mesh");
  const PlyCloud mesh = test::mesh_on_surface(surface_grid(sequence, 16));
  write_ply_cloud(dir / "mesh.ply", mesh);

  const MapEvalRun run = map_eval(dir / "mesh.ply", sequence);
  std::printf("%s", run.result.out.c_str());
  const size_t samples = run.map["points"].get<size_t>();
  EXPECT_NE(run.result.out.find("judged a mesh of " + std::to_string(mesh.triangles.size()) +
                                " triangles sampled as " + std::to_string(samples) + " points"),
            std::string::npos)
      << run.result.out;
  EXPECT_EQ(run.map["mesh_triangles"], mesh.triangles.size());
  EXPECT_GT(samples, 20 * mesh.points.size());
  EXPECT_LT(run.map["accuracy"]["max"].get<double>(), 1e-5);
}

}  // namespace
}  // namespace slamkit::eval
