#pragma once
// Test helpers for PLY files: a second PLY reader, independent of slamkit's, and random clouds.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fusion/ply_cloud.h"

namespace slamkit::test {

inline std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A second PLY reader, written from the format as Open3D (rply) and CloudCompare expect it:
// "ply", a format line, elements with their properties, "end_header"; then the vertex rows
// and the face rows. It accepts exactly the layouts write_ply_cloud promises (x y z float,
// nx ny nz float or none, red green blue uchar; faces as lists of uchar length and int
// indices) and other elements only when empty.
struct PlyFile {
  std::string format;
  size_t vertices = 0;
  size_t faces = 0;
  size_t header_bytes = 0;
  PlyCloud cloud;
};

inline PlyFile parse_ply(const std::filesystem::path& path) {
  const std::string bytes = file_bytes(path);
  PlyFile ply;
  std::istringstream header(bytes);
  std::string line;
  std::getline(header, line);
  EXPECT_EQ(line, "ply");
  std::vector<std::string> properties, face_properties;
  std::string element;
  while (std::getline(header, line) && line != "end_header") {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string version;
      words >> ply.format >> version;
      EXPECT_EQ(version, "1.0");
    } else if (keyword == "element") {
      size_t count = 0;
      words >> element >> count;
      if (element == "vertex")
        ply.vertices = count;
      else if (element == "face")
        ply.faces = count;
      else
        EXPECT_EQ(count, 0u) << "unexpected non-empty element " << element;
    } else if (keyword == "property") {
      const std::string rest = line.substr(line.find(' ') + 1);
      if (element == "vertex") properties.push_back(rest);
      if (element == "face") face_properties.push_back(rest);
    } else {
      EXPECT_TRUE(keyword == "comment" || keyword == "obj_info") << line;
    }
  }
  EXPECT_EQ(line, "end_header");
  ply.header_bytes = size_t(header.tellg());
  const bool normals = properties.size() == 9;
  std::vector<std::string> expected = {"float x", "float y", "float z"};
  if (normals) expected.insert(expected.end(), {"float nx", "float ny", "float nz"});
  expected.insert(expected.end(), {"uchar red", "uchar green", "uchar blue"});
  EXPECT_EQ(properties, expected);
  if (ply.faces > 0) {
    EXPECT_EQ(face_properties, std::vector<std::string>{"list uchar int vertex_indices"});
  }
  const auto add_vertex = [&](const float* xyz, const float* n, const int* rgb) {
    ply.cloud.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    if (normals) ply.cloud.normals.emplace_back(n[0], n[1], n[2]);
    ply.cloud.colours.push_back({uint8_t(rgb[0]), uint8_t(rgb[1]), uint8_t(rgb[2])});
  };
  if (ply.format == "binary_little_endian") {
    const size_t row = (normals ? 6 : 3) * sizeof(float) + 3, face_row = 1 + 3 * sizeof(int32_t);
    EXPECT_EQ(bytes.size(), ply.header_bytes + ply.vertices * row + ply.faces * face_row) << path;
    const char* at = bytes.data() + ply.header_bytes;
    const char* end = bytes.data() + bytes.size();
    for (size_t i = 0; i < ply.vertices && at + row <= end; ++i, at += row) {
      float values[6] = {};  // x86: little-endian already
      std::memcpy(values, at, row - 3);
      const int rgb[3] = {uint8_t(at[row - 3]), uint8_t(at[row - 2]), uint8_t(at[row - 1])};
      add_vertex(values, values + 3, rgb);
    }
    for (size_t i = 0; i < ply.faces && at + face_row <= end; ++i, at += face_row) {
      EXPECT_EQ(at[0], 3);
      int32_t v[3];
      std::memcpy(v, at + 1, sizeof v);
      ply.cloud.triangles.push_back({uint32_t(v[0]), uint32_t(v[1]), uint32_t(v[2])});
    }
  } else {
    EXPECT_EQ(ply.format, "ascii");
    for (size_t i = 0; i < ply.vertices; ++i) {
      float xyz[3] = {}, n[3] = {};
      int rgb[3] = {-1, -1, -1};
      header >> xyz[0] >> xyz[1] >> xyz[2];
      if (normals) header >> n[0] >> n[1] >> n[2];
      header >> rgb[0] >> rgb[1] >> rgb[2];
      add_vertex(xyz, n, rgb);
    }
    for (size_t i = 0; i < ply.faces; ++i) {
      int count = 0;
      uint32_t a = 0, b = 0, c = 0;
      header >> count >> a >> b >> c;
      EXPECT_EQ(count, 3);
      ply.cloud.triangles.push_back({a, b, c});
    }
    EXPECT_TRUE(header) << "fewer rows than the header says";
    std::string rest;
    header >> rest;
    EXPECT_TRUE(rest.empty()) << "more rows than the header says";
  }
  return ply;
}

inline PlyCloud random_cloud(size_t n) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> coordinate(-4.0f, 4.0f);
  std::uniform_int_distribution<int> channel(0, 255);
  PlyCloud cloud;
  for (size_t i = 0; i < n; ++i) {
    cloud.points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    cloud.colours.push_back({uint8_t(channel(rng)), uint8_t(channel(rng)), uint8_t(channel(rng))});
  }
  return cloud;
}

}  // namespace slamkit::test
