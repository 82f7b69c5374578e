// read_ply_cloud on PLY files as other programs write them: one hand-written file per case
// (ascii, both binary byte orders, every scalar type, normals and extra properties, extra
// elements, faces), files written by PCL and by Open3D, and the refusals, each naming the file,
// the reason and the header or body line at fault.
#include <gtest/gtest.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "fusion/ply_cloud.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

void write_file(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A binary body in either byte order (the test machine is little-endian, as x86 is).
class Body {
 public:
  explicit Body(bool big_endian) : big_endian_(big_endian) {}
  template <typename T>
  Body& put(T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof value);
    if (big_endian_) std::reverse(bytes, bytes + sizeof bytes);
    bytes_.append(bytes, sizeof bytes);
    return *this;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  bool big_endian_;
  std::string bytes_;
};

std::string format_line(bool big_endian) {
  return big_endian ? "format binary_big_endian 1.0\n" : "format binary_little_endian 1.0\n";
}

// The points and colours most cases hold; exact in float and in short decimal text.
const std::vector<Eigen::Vector3f> kPoints = {
    {0.5f, -1.25f, 2}, {1e-3f, 3.75f, -0.125f}, {-2.5f, 0, 1.5f}};
const std::vector<Rgb8> kColours = {{255, 0, 10}, {1, 2, 3}, {128, 64, 32}};
const char* const kXyzRgb =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "property uchar red\nproperty uchar green\nproperty uchar blue\n";
const char* const kXyzRgbRows =
    "0.5 -1.25 2 255 0 10\n0.001 3.75 -0.125 1 2 3\n-2.5 0 1.5 128 64 32\n";

std::string xyz_rgb_body(bool big_endian) {
  Body body(big_endian);
  for (size_t i = 0; i < kPoints.size(); ++i) {
    body.put(kPoints[i].x()).put(kPoints[i].y()).put(kPoints[i].z());
    for (const uint8_t c : kColours[i]) body.put(c);
  }
  return body.bytes();
}

void expect_points_and_colours(const PlyCloud& cloud) {
  EXPECT_EQ(cloud.points, kPoints);
  EXPECT_EQ(cloud.colours, kColours);
  EXPECT_TRUE(cloud.normals.empty());
  EXPECT_TRUE(cloud.triangles.empty());
}

TEST(PlyFormats, AsciiWithCommentsObjInfoAndWindowsLineEnds) {
  const fs::path dir = test::temp_dir("ply_ascii");
  const std::string text = std::string("ply\nformat ascii 1.0\ncomment made by hand\n") +
                           "obj_info written for a test\n" + kXyzRgb + "end_header\n" + kXyzRgbRows;
  write_file(dir / "ascii.ply", text);
  expect_points_and_colours(read_ply_cloud(dir / "ascii.ply"));
  std::string crlf;
  for (const char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  write_file(dir / "crlf.ply", crlf);
  expect_points_and_colours(read_ply_cloud(dir / "crlf.ply"));
}

TEST(PlyFormats, BinaryLittleAndBigEndian) {
  const fs::path dir = test::temp_dir("ply_binary");
  for (const bool big_endian : {false, true}) {
    const fs::path file = dir / (big_endian ? "big.ply" : "little.ply");
    write_file(file, "ply\n" + format_line(big_endian) + kXyzRgb + "end_header\n" +
                         xyz_rgb_body(big_endian));
    SCOPED_TRACE(file);
    expect_points_and_colours(read_ply_cloud(file));
  }
}

TEST(PlyFormats, DoubleCoordinatesAreRoundedToFloatNotLeftAtZero) {
  // The layout Open3D writes, whose points PCL's typed loader left at the origin.
  const fs::path dir = test::temp_dir("ply_double");
  const std::vector<Eigen::Vector3d> points = {{0.1, 0.2, 0.3}, {-1.0 / 3, 1e-7, 12345.678}};
  Body body(false);
  for (const Eigen::Vector3d& p : points) body.put(p.x()).put(p.y()).put(p.z());
  write_file(dir / "double.ply",
             "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\n"
             "property double y\nproperty float64 z\nend_header\n" +
                 body.bytes());
  const PlyCloud cloud = read_ply_cloud(dir / "double.ply");
  ASSERT_EQ(cloud.points.size(), 2u);
  for (size_t i = 0; i < 2; ++i) EXPECT_EQ(cloud.points[i], points[i].cast<float>()) << i;
  EXPECT_EQ(cloud.colours, std::vector<Rgb8>(2, Rgb8{0, 0, 0}));  // no colour in the file
}

TEST(PlyFormats, CoordinatesOfEveryScalarTypeInBothSpellings) {
  const fs::path dir = test::temp_dir("ply_types");
  const auto header = [](const std::string& format, const char* x, const char* y, const char* z) {
    return "ply\n" + format + "element vertex 1\nproperty " + x + " x\nproperty " + y +
           " y\nproperty " + z + " z\nend_header\n";
  };
  const std::string ascii = "format ascii 1.0\n", binary = format_line(false);
  write_file(dir / "a.ply",
             header(binary, "char", "uchar", "short") +
                 Body(false).put(int8_t(-5)).put(uint8_t(200)).put(int16_t(-300)).bytes());
  write_file(
      dir / "b.ply",
      header(binary, "ushort", "int", "uint") +
          Body(false).put(uint16_t(60000)).put(int32_t(-70000)).put(uint32_t(4000000000u)).bytes());
  write_file(dir / "c.ply",
             header(binary, "int8", "uint8", "int16") +
                 Body(false).put(int8_t(-5)).put(uint8_t(200)).put(int16_t(-300)).bytes());
  write_file(
      dir / "d.ply",
      header(binary, "uint16", "int32", "uint32") +
          Body(false).put(uint16_t(60000)).put(int32_t(-70000)).put(uint32_t(4000000000u)).bytes());
  write_file(dir / "e.ply", header(binary, "float32", "float", "double") +
                                Body(false).put(0.25f).put(-8.5f).put(10.0).bytes());
  write_file(dir / "f.ply", header(ascii, "char", "uchar", "short") + "-5 200 -300\n");
  write_file(dir / "g.ply", header(ascii, "uint16", "int32", "uint") + "60000 -70000 4000000000\n");
  const Eigen::Vector3f small(-5, 200, -300), large(60000, -70000, 4e9f);
  for (const char* name : {"a.ply", "c.ply", "f.ply"})
    EXPECT_EQ(read_ply_points(dir / name), std::vector<Eigen::Vector3f>{small}) << name;
  for (const char* name : {"b.ply", "d.ply", "g.ply"})
    EXPECT_EQ(read_ply_points(dir / name), std::vector<Eigen::Vector3f>{large}) << name;
  EXPECT_EQ(read_ply_points(dir / "e.ply"),
            std::vector<Eigen::Vector3f>{Eigen::Vector3f(0.25f, -8.5f, 10)});
}

TEST(PlyFormats, NormalsAreReadAndExtraPropertiesSkipped) {
  const fs::path dir = test::temp_dir("ply_normals");
  const std::string header =
      "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty double nz\nproperty uchar red\n"
      "property uchar green\nproperty uchar blue\nproperty uchar alpha\n"
      "property float curvature\nproperty float intensity\nproperty double scalar_Distance\n"
      "property list uchar int neighbours\nend_header\n";
  Body body(false);
  body.put(1.0f)
      .put(2.0f)
      .put(3.0f)
      .put(0.0f)
      .put(0.6f)
      .put(0.8)
      .put(uint8_t(9))
      .put(uint8_t(8))
      .put(uint8_t(7))
      .put(uint8_t(128))
      .put(0.5f)
      .put(100.0f)
      .put(-1.5)
      .put(uint8_t(2))
      .put(int32_t(1))
      .put(int32_t(0));
  body.put(-1.0f)
      .put(-2.0f)
      .put(-3.0f)
      .put(1.0f)
      .put(0.0f)
      .put(0.0)
      .put(uint8_t(1))
      .put(uint8_t(2))
      .put(uint8_t(3))
      .put(uint8_t(255))
      .put(0.0f)
      .put(0.0f)
      .put(0.0)
      .put(uint8_t(0));
  write_file(dir / "binary.ply", "ply\n" + format_line(false) + header + body.bytes());
  write_file(dir / "ascii.ply", "ply\nformat ascii 1.0\n" + header +
                                    "1 2 3 0 0.6 0.8 9 8 7 128 0.5 100 -1.5 2 1 0\n"
                                    "-1 -2 -3 1 0 0 1 2 3 255 0 0 0 0\n");
  for (const char* name : {"binary.ply", "ascii.ply"}) {
    SCOPED_TRACE(name);
    const PlyCloud cloud = read_ply_cloud(dir / name);
    EXPECT_EQ(cloud.points, (std::vector<Eigen::Vector3f>{{1, 2, 3}, {-1, -2, -3}}));
    EXPECT_EQ(cloud.normals, (std::vector<Eigen::Vector3f>{{0, 0.6f, 0.8f}, {1, 0, 0}}));
    EXPECT_EQ(cloud.colours, (std::vector<Rgb8>{{9, 8, 7}, {1, 2, 3}}));
  }
}

TEST(PlyFormats, ColoursAsFloatUshortAndDiffuse) {
  const fs::path dir = test::temp_dir("ply_colours");
  const std::string xyz =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\n";
  write_file(dir / "float.ply", xyz +
                                    "property float red\nproperty float green\n"
                                    "property double blue\nend_header\n"
                                    "0 0 1 1.0 0.5 0\n0 0 2 1.5 -0.25 0.2\n");
  write_file(dir / "ushort.ply", xyz +
                                     "property ushort diffuse_red\nproperty ushort diffuse_green\n"
                                     "property ushort diffuse_blue\nend_header\n"
                                     "0 0 1 65535 256 255\n0 0 2 0 32768 1000\n");
  EXPECT_EQ(read_ply_cloud(dir / "float.ply").colours,
            (std::vector<Rgb8>{{255, 128, 0}, {255, 0, 51}}));  // clamped to 0..1
  EXPECT_EQ(read_ply_cloud(dir / "ushort.ply").colours,
            (std::vector<Rgb8>{{255, 1, 0}, {0, 128, 3}}));
}

TEST(PlyFormats, OtherElementsBeforeAndAfterTheVerticesAreSkipped) {
  const fs::path dir = test::temp_dir("ply_elements");
  const std::string before =
      "element camera 1\nproperty float view_px\nproperty float view_py\n"
      "property list uchar float k\n";
  const std::string after =
      "element edge 2\nproperty int vertex1\nproperty int vertex2\n"
      "element material 1\nproperty list ushort uchar name\nproperty float shininess\n"
      "element face 0\nend_header\n";
  for (const bool big_endian : {false, true}) {
    Body camera(big_endian), rest(big_endian);
    camera.put(1.5f).put(-2.0f).put(uint8_t(2)).put(3.0f).put(4.0f);
    rest.put(int32_t(0)).put(int32_t(1)).put(int32_t(1)).put(int32_t(2));
    rest.put(uint16_t(3)).put(uint8_t('a')).put(uint8_t('b')).put(uint8_t('c')).put(0.25f);
    const fs::path file = dir / (big_endian ? "big.ply" : "little.ply");
    write_file(file, "ply\n" + format_line(big_endian) + before + kXyzRgb + after + camera.bytes() +
                         xyz_rgb_body(big_endian) + rest.bytes());
    SCOPED_TRACE(file);
    expect_points_and_colours(read_ply_cloud(file));
  }
  write_file(dir / "ascii.ply", "ply\nformat ascii 1.0\n" + before + kXyzRgb + after +
                                    "1.5 -2 2 3 4\n" + kXyzRgbRows + "0 1\n1 2\n3 97 98 99 0.25\n");
  expect_points_and_colours(read_ply_cloud(dir / "ascii.ply"));
}

TEST(PlyFormats, FacesAreTrianglesWithPolygonsFanned) {
  const fs::path dir = test::temp_dir("ply_faces");
  const std::string vertices =
      "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string rows = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n-1 0.5 0\n";
  const std::vector<std::array<uint32_t, 3>> expected = {{0, 1, 2}, {0, 1, 2}, {0, 2, 3},
                                                         {4, 3, 2}, {4, 2, 1}, {4, 1, 0}};
  // A triangle, a quad, a pentagon; a colour per face to skip.
  Body body(false);
  for (int i = 0; i < 5; ++i) body.put(float(i)).put(0.0f).put(0.0f);
  body.put(uint8_t(3)).put(uint32_t(0)).put(uint32_t(1)).put(uint32_t(2)).put(uint8_t(7));
  body.put(uint8_t(4))
      .put(uint32_t(0))
      .put(uint32_t(1))
      .put(uint32_t(2))
      .put(uint32_t(3))
      .put(uint8_t(7));
  body.put(uint8_t(5))
      .put(uint32_t(4))
      .put(uint32_t(3))
      .put(uint32_t(2))
      .put(uint32_t(1))
      .put(uint32_t(0))
      .put(uint8_t(7));
  write_file(dir / "binary.ply", "ply\n" + format_line(false) + vertices +
                                     "element face 3\nproperty list uchar uint vertex_indices\n"
                                     "property uchar red\nend_header\n" +
                                     body.bytes());
  // Faces before vertices, "vertex_index" and other list types.
  write_file(dir / "ascii.ply",
             "ply\nformat ascii 1.0\nelement face 3\nproperty list int int vertex_index\n" +
                 vertices + "end_header\n3 0 1 2\n4 0 1 2 3\n5 4 3 2 1 0\n" + rows);
  for (const char* name : {"binary.ply", "ascii.ply"}) {
    const PlyCloud mesh = read_ply_cloud(dir / name);
    EXPECT_EQ(mesh.triangles, expected) << name;
    EXPECT_EQ(mesh.points.size(), 5u) << name;
  }
}

TEST(PlyFormats, PclsOwnWriterReadsBackEqual) {
  const fs::path dir = test::temp_dir("ply_pcl");
  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud;
  for (int i = 0; i < 50; ++i) {
    pcl::PointXYZRGBNormal p;
    // Eighths: exact in float and in PCL's ASCII text.
    p.x = 0.125f * float(i), p.y = -0.5f * float(i % 7), p.z = 1 + 0.25f * float(i % 3);
    p.r = uint8_t(5 * i), p.g = uint8_t(255 - i), p.b = uint8_t(i % 2 ? 0 : 200);
    p.normal_x = i % 2 ? 1.0f : 0.0f, p.normal_y = 0, p.normal_z = i % 2 ? 0.0f : -1.0f;
    p.curvature = 0.125f;
    cloud.push_back(p);
  }
  // With PCL's camera element after the vertices (use_camera's default).
  ASSERT_EQ(pcl::io::savePLYFileBinary((dir / "binary.ply").string(), cloud), 0);
  ASSERT_EQ(pcl::io::savePLYFileASCII((dir / "ascii.ply").string(), cloud), 0);
  for (const char* name : {"binary.ply", "ascii.ply"}) {
    SCOPED_TRACE(name);
    const PlyCloud back = read_ply_cloud(dir / name);
    ASSERT_EQ(back.points.size(), cloud.size());
    ASSERT_EQ(back.normals.size(), cloud.size());
    for (size_t i = 0; i < cloud.size(); ++i) {
      const pcl::PointXYZRGBNormal& p = cloud[i];
      EXPECT_EQ(back.points[i], p.getVector3fMap()) << i;
      EXPECT_EQ(back.normals[i], p.getNormalVector3fMap()) << i;
      EXPECT_EQ(back.colours[i], (Rgb8{p.r, p.g, p.b})) << i;
    }
  }
}

// Made once with Debian's python3-open3d 0.16 (Open3D is not available in CI), in
// tests/fusion/data:
//   pts = [(0.1 * i, 0.2 * j - 0.3, 1.0 + 0.01 * (i + j)) for i in range(5) for j in range(4)]
//   pcd = o3d.geometry.PointCloud(); pcd.points = o3d.utility.Vector3dVector(np.array(pts))
//   pcd.normals = ... (0.6, 0.8, 0) for even k, else (0, 0, -1)
//   pcd.colors = ... (k / 255, 10 * k / 255, 1) for point k
//   o3d.io.write_point_cloud("open3d_cloud.ply", pcd)
//   mesh = o3d.geometry.TriangleMesh.create_box(width=0.4, height=0.2, depth=0.1)
//   mesh.translate((-0.2, 0.5, 1.25)); mesh.compute_vertex_normals()
//   mesh.vertex_colors = ... (1, 0, k / 255) for vertex k
//   o3d.io.write_triangle_mesh("open3d_mesh.ply", mesh)
// Both are binary little-endian: double x y z, double nx ny nz, uchar red green blue; the
// mesh adds "element face 12 / property list uchar uint vertex_indices".
const fs::path kOpen3dData = fs::path(SLAMKIT_SOURCE_DIR) / "tests" / "fusion" / "data";

TEST(PlyFormats, Open3dPointCloudReadsTheCoordinatesWritten) {
  const PlyCloud cloud = read_ply_cloud(kOpen3dData / "open3d_cloud.ply");
  ASSERT_EQ(cloud.points.size(), 20u);
  ASSERT_EQ(cloud.normals.size(), 20u);
  for (int i = 0, k = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j, ++k) {
      const Eigen::Vector3d written(0.1 * i, 0.2 * j - 0.3, 1.0 + 0.01 * (i + j));
      EXPECT_EQ(cloud.points[k], written.cast<float>()) << k;
      EXPECT_EQ(cloud.normals[k],
                k % 2 ? Eigen::Vector3f(0, 0, -1) : Eigen::Vector3d(0.6, 0.8, 0).cast<float>())
          << k;
      EXPECT_EQ(cloud.colours[k], (Rgb8{uint8_t(k), uint8_t(10 * k), 255})) << k;
    }
  EXPECT_TRUE(cloud.triangles.empty());
}

TEST(PlyFormats, Open3dMeshReadsItsVerticesAndTriangles) {
  const PlyCloud mesh = read_ply_cloud(kOpen3dData / "open3d_mesh.ply");
  ASSERT_EQ(mesh.points.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    // create_box's corner k: bit 0 the far x, bit 1 the far z, bit 2 the far y; translated.
    const Eigen::Vector3d written(k & 1 ? 0.4 - 0.2 : -0.2, k & 4 ? 0.2 + 0.5 : 0.5,
                                  k & 2 ? 0.1 + 1.25 : 1.25);
    EXPECT_EQ(mesh.points[k], written.cast<float>()) << k;
    EXPECT_NEAR(mesh.normals[k].norm(), 1.0f, 1e-6f) << k;
    EXPECT_EQ(mesh.colours[k], (Rgb8{255, 0, uint8_t(k)})) << k;
  }
  EXPECT_EQ(mesh.triangles, (std::vector<std::array<uint32_t, 3>>{{4, 7, 5},
                                                                  {4, 6, 7},
                                                                  {0, 2, 4},
                                                                  {2, 6, 4},
                                                                  {0, 1, 2},
                                                                  {1, 3, 2},
                                                                  {1, 5, 7},
                                                                  {1, 7, 3},
                                                                  {2, 3, 7},
                                                                  {2, 7, 6},
                                                                  {0, 4, 1},
                                                                  {1, 4, 5}}));
}

struct BadFile {
  const char* what;
  std::string bytes;
  int line;  // where the message must point, 0: no line
  const char* reason;
};

std::string read_error(const fs::path& file) {
  try {
    read_ply_cloud(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PlyFormats, BadFilesAreRefusedNamingTheFileTheReasonAndTheLine) {
  const fs::path dir = test::temp_dir("ply_refusals");
  const std::string ply = "ply\nformat ascii 1.0\n";
  const std::string xyz =
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string one_row = xyz + "end_header\n1 2 3\n";
  const std::string rgb = "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  const std::string binary_xyz = "ply\n" + format_line(false) + xyz + "end_header\n";
  const std::string faces = ply +
                            "element vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement face 1\n";
  const std::string face_rows = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string twelve_bytes(12, '\0');
  const std::vector<BadFile> cases = {
      {"not ply", "plx\n" + one_row, 0, "not a PLY file"},
      {"binary noise", std::string("\x89PNG\r\n\x1a\n", 8), 0, "not a PLY file"},
      {"unknown format", "ply\nformat binary_middle_endian 1.0\n" + one_row, 2,
       "unknown PLY format \"binary_middle_endian\""},
      {"version", "ply\nformat ascii 2.0\n" + one_row, 2, "unsupported PLY version \"2.0\""},
      {"no format", "ply\n" + one_row, 6, "without a format line"},
      {"two formats", ply + "format ascii 1.0\n" + one_row, 3, "a second format line"},
      {"no vertex", ply + "element face 0\nend_header\n", 4, "no element vertex"},
      {"no z", ply + "element vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n", 3,
       "element vertex has no property z"},
      {"unknown type",
       ply + "element vertex 1\nproperty float x\nproperty float y\n"
             "property float16 z\nend_header\n1 2 3\n",
       6, "unknown property type \"float16\""},
      {"element words", ply + "element vertex 1 extra\n", 3, "expected \"element NAME COUNT\""},
      {"property words", ply + xyz.substr(0, xyz.size() - 1) + " junk\n", 6,
       "expected \"property TYPE NAME\""},
      {"end_header words", ply + xyz + "end_header junk\n1 2 3\n", 7, "expected \"end_header\""},
      {"unknown keyword", ply + "elements vertex 1\n", 3, "unknown header line"},
      {"count", ply + "element vertex 1.5\n", 3, "not a whole number"},
      {"no end", ply + xyz, 0, "never ends"},
      {"property first", ply + "property float x\n" + one_row, 3, "a property before any element"},
      {"property twice", ply + xyz + "property float x\nend_header\n1 2 3 4\n", 7,
       "a second property x"},
      {"element twice", ply + xyz + xyz + "end_header\n1 2 3\n1 2 3\n", 7,
       "a second element vertex"},
      {"rows without properties", ply + "element camera 2\n" + one_row, 3,
       "has 2 rows but no property"},
      {"list x",
       ply + "element vertex 1\nproperty list uchar float x\nproperty float y\n"
             "property float z\nend_header\n1 1 2 3\n",
       4, "vertex x is a list"},
      {"some colours", ply + xyz + "property uchar red\nend_header\n1 2 3 4\n", 3,
       "only some of red, green, blue"},
      {"int colour",
       ply + xyz +
           "property int red\nproperty int green\nproperty int blue\n"
           "end_header\n1 2 3 4 5 6\n",
       7, "colour red of type int"},
      {"int normals",
       ply + xyz +
           "property short nx\nproperty short ny\nproperty short nz\n"
           "end_header\n1 2 3 0 0 1\n",
       7, "normal nx of type short"},
      {"list length type", faces + "property list float int vertex_indices\nend_header\n", 8,
       "not an integer type"},
      {"face without indices", faces + "property int flags\nend_header\n" + face_rows + "0\n", 7,
       "element face has no vertex_indices list"},
      {"binary short", binary_xyz + std::string(11, '\0'), 3, "shorter than its header promises"},
      {"absurd count",
       ply + "element vertex 4000000000\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n1 2 3\n",
       3, "4000000000 rows cannot fit"},
      {"binary trailing bytes", binary_xyz + twelve_bytes + "abc", 0,
       "3 bytes after the last element"},
      {"ascii rows missing",
       ply + "element vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nend_header\n1.5 2.5 3.5\n4.5 5.5 6.5\n",
       9, "ends before vertex 2 of 3"},
      {"ascii not a number", ply + xyz + "end_header\n1 2 abc\n", 8,
       "\"abc\" is not a float value"},
      {"ascii fewer values", ply + xyz + "end_header\n1.0 2.0\n", 8, "fewer values"},
      {"ascii more values", ply + xyz + "end_header\n1 2 3 4\n", 8, "more values"},
      {"ascii trailing text", ply + one_row + "4 5 6\n", 9, "text after the last element"},
      {"uchar out of range", ply + xyz + rgb + "end_header\n1 2 3 256 0 0\n", 11,
       "256 is out of range for uchar"},
      {"float out of range", ply + xyz + "end_header\n1 2 1e39\n", 8,
       "1e39 is out of range for float"},
      {"face of two",
       faces + "property list uchar int vertex_indices\nend_header\n" + face_rows + "2 0 1\n", 13,
       "face 0 of 1 has 2 vertices, fewer than a face's 3"},
      {"face index",
       faces + "property list uchar int vertex_indices\nend_header\n" + face_rows + "3 0 1 7\n", 13,
       "refers to vertex 7, but the file has 3 vertices"},
      {"negative index",
       faces + "property list uchar int vertex_indices\nend_header\n" + face_rows + "3 0 -1 2\n",
       13, "refers to vertex -1"},
      {"negative length",
       faces + "property list int int vertex_indices\nend_header\n" + face_rows + "-3 0 1 2\n", 13,
       "of length -3"},
      {"binary list past the end",
       "ply\n" + format_line(false) +
           "element vertex 1\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
           "end_header\n" +
           twelve_bytes + "\x03" + std::string(8, '\0'),
       0, "the file ends inside face 0 of 1"},
  };
  for (const BadFile& bad : cases) {
    SCOPED_TRACE(bad.what);
    const fs::path file = dir / (std::string(bad.what) + ".ply");
    write_file(file, bad.bytes);
    const std::string message = read_error(file);
    const std::string where =
        file.string() + (bad.line > 0 ? ":" + std::to_string(bad.line) + ": " : ": ");
    EXPECT_EQ(message.rfind(where, 0), 0u) << message;
    EXPECT_NE(message.find(bad.reason), std::string::npos) << message;
  }
}

// Truncated and corrupted files are read or refused with an InputError: never a crash, an
// out-of-bounds read (the sanitizer builds run this) or another exception.
TEST(PlyFormats, DamagedFilesAreReadOrRefusedNeverACrash) {
  const fs::path dir = test::temp_dir("ply_damaged");
  PlyCloud mesh;
  for (int i = 0; i < 6; ++i) {
    mesh.points.emplace_back(float(i), float(i * i), 0.5f);
    mesh.colours.push_back({uint8_t(i), 0, 0});
    mesh.normals.emplace_back(0, 0, 1);
  }
  mesh.triangles = {{0, 1, 2}, {2, 3, 4}, {3, 4, 5}};
  for (const bool binary : {true, false}) {
    write_ply_cloud(dir / "good.ply", mesh, binary);
    std::ifstream in(dir / "good.ply", std::ios::binary);
    const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> damaged;
    for (size_t size = 0; size < good.size(); ++size) damaged.push_back(good.substr(0, size));
    for (size_t at = 0; at < good.size(); ++at)
      for (const char c : {'\0', '\xff', '\n', ' ', '9', '-', 'e'}) {
        damaged.push_back(good);
        damaged.back()[at] = c;
      }
    // A file each: truncating a file to rewrite it takes milliseconds on some disks.
    for (size_t i = 0; i < damaged.size(); ++i) {
      const fs::path file = dir / (std::to_string(binary) + "_" + std::to_string(i) + ".ply");
      write_file(file, damaged[i]);
      try {
        read_ply_cloud(file);
      } catch (const InputError&) {
      }
    }
  }
}

}  // namespace
}  // namespace slamkit
