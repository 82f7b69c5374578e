// PLY files as write_ply_cloud writes them: read back exactly (binary and ASCII), with normals
// and faces, checked by read_ply_cloud and by an independent reader; the header is the plain
// one every reader takes; bad files and clouds are errors naming their path.
#include "fusion/ply_cloud.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "ply_reader.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;
using test::file_bytes;
using test::parse_ply;
using test::random_cloud;

// random_cloud with unit normals and triangles over its points.
PlyCloud random_mesh(size_t n) {
  PlyCloud mesh = random_cloud(n);
  for (size_t i = 0; i < n; ++i) {
    mesh.normals.push_back(mesh.points[(i + 1) % n].normalized());
    if (i + 2 < n) mesh.triangles.push_back({uint32_t(i), uint32_t(i + 1), uint32_t(i + 2)});
  }
  return mesh;
}

void expect_same_cloud(const PlyCloud& back, const PlyCloud& cloud) {
  ASSERT_EQ(back.points.size(), cloud.points.size());
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    EXPECT_EQ(back.points[i], cloud.points[i]) << i;
    EXPECT_EQ(back.colours[i], cloud.colours[i]) << i;
  }
  EXPECT_EQ(back.normals, cloud.normals);
  EXPECT_EQ(back.triangles, cloud.triangles);
}

TEST(PlyCloud, BinaryAndAsciiRoundTripsAreExact) {
  const fs::path dir = test::temp_dir("ply_round_trip");
  for (const PlyCloud& cloud : {random_cloud(1000), random_mesh(1000)}) {
    write_ply_cloud(dir / "binary.ply", cloud, true);
    write_ply_cloud(dir / "ascii.ply", cloud, false);
    EXPECT_FALSE(fs::exists(temporary_path(dir / "binary.ply")));
    for (const char* name : {"binary.ply", "ascii.ply"}) {
      SCOPED_TRACE(name);
      expect_same_cloud(read_ply_cloud(dir / name), cloud);
      expect_same_cloud(parse_ply(dir / name).cloud, cloud);
    }
    EXPECT_EQ(read_ply_points(dir / "binary.ply"), cloud.points);
  }
}

TEST(PlyCloud, HeaderIsThePlainOneAndTheBytesDependOnTheCloudAlone) {
  const fs::path dir = test::temp_dir("ply_header");
  PlyCloud mesh;
  mesh.points = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  mesh.colours = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  mesh.normals = {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}};
  mesh.triangles = {{0, 1, 2}};
  write_ply_cloud(dir / "mesh.ply", mesh, false);
  EXPECT_EQ(file_bytes(dir / "mesh.ply"),
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
            "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
            "property list uchar int vertex_indices\nend_header\n"
            "0 0 1 0 0 -1 255 0 0\n1 0 1 0 0 -1 0 255 0\n0 1 1 0 0 -1 0 0 255\n3 0 1 2\n");

  const PlyCloud cloud = random_cloud(100);
  write_ply_cloud(dir / "one.ply", cloud);
  write_ply_cloud(dir / "two.ply", cloud);
  const std::string bytes = file_bytes(dir / "one.ply");
  EXPECT_TRUE(bytes == file_bytes(dir / "two.ply"));
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\n"
      "property float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nend_header\n";
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  EXPECT_EQ(bytes.size(), header.size() + 100 * 15);
}

TEST(PlyCloud, BadFilesAndCloudsAreInputErrorsNamingThePathAndTheReason) {
  const fs::path dir = test::temp_dir("ply_bad");
  const auto expect_error = [](const fs::path& path, const std::string& reason,
                               const auto& action) {
    try {
      action();
      ADD_FAILURE() << "expected InputError for " << path;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  };
  expect_error(dir / "missing.ply", "not found", [&] { read_ply_cloud(dir / "missing.ply"); });
  expect_error(dir, "not a file", [&] { read_ply_cloud(dir); });
  std::ofstream(dir / "text.ply") << "not a ply\n";
  expect_error(dir / "text.ply", "not a PLY file", [&] { read_ply_cloud(dir / "text.ply"); });
  expect_error(dir / "empty.ply", "no point", [&] { write_ply_cloud(dir / "empty.ply", {}); });
  PlyCloud uneven = random_cloud(3);
  uneven.colours.pop_back();
  expect_error(dir / "uneven.ply", "3 points with 2 colours",
               [&] { write_ply_cloud(dir / "uneven.ply", uneven); });
  PlyCloud few_normals = random_mesh(3);
  few_normals.normals.pop_back();
  expect_error(dir / "normals.ply", "3 points with 2 normals",
               [&] { write_ply_cloud(dir / "normals.ply", few_normals); });
  PlyCloud stray = random_mesh(3);
  stray.triangles.push_back({0, 1, 3});
  expect_error(dir / "stray.ply", "triangle 1: it refers to vertex 3 of 3",
               [&] { write_ply_cloud(dir / "stray.ply", stray); });
  std::ofstream(dir / "blocker") << "a file, not a folder";
  const fs::path unwritable = dir / "blocker" / "map.ply";
  expect_error(unwritable, "cannot write", [&] { write_ply_cloud(unwritable, random_cloud(3)); });
  for (const char* name : {"empty.ply", "uneven.ply", "normals.ply", "stray.ply"})
    EXPECT_FALSE(fs::exists(dir / name)) << name;
}

}  // namespace
}  // namespace slamkit
