#pragma once
// Test helpers for PLY files: a second PLY reader, independent of PCL's, and random clouds.
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
// "ply", a format line, elements with their properties, "end_header"; then the vertex rows.
// It accepts exactly the layout the map promises (x y z float, red green blue uchar) and
// other elements only when empty.
struct PlyFile {
  std::string format;
  size_t vertices = 0;
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
  std::vector<std::string> properties;
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
      else
        EXPECT_EQ(count, 0u) << "unexpected non-empty element " << element;
    } else if (keyword == "property") {
      std::string type, name;
      words >> type >> name;
      if (element == "vertex") properties.push_back(type + " " + name);
    } else {
      EXPECT_TRUE(keyword == "comment" || keyword == "obj_info") << line;
    }
  }
  EXPECT_EQ(line, "end_header");
  ply.header_bytes = size_t(header.tellg());
  EXPECT_EQ(properties, (std::vector<std::string>{"float x", "float y", "float z", "uchar red",
                                                  "uchar green", "uchar blue"}));
  if (ply.format == "binary_little_endian") {
    constexpr size_t kRow = 3 * sizeof(float) + 3;
    EXPECT_EQ(bytes.size(), ply.header_bytes + ply.vertices * kRow) << path;
    for (size_t i = 0; i < ply.vertices && ply.header_bytes + (i + 1) * kRow <= bytes.size(); ++i) {
      const char* row = bytes.data() + ply.header_bytes + i * kRow;
      Eigen::Vector3f p;
      std::memcpy(p.data(), row, 3 * sizeof(float));  // x86: little-endian already
      ply.cloud.points.push_back(p);
      ply.cloud.colours.push_back({uint8_t(row[12]), uint8_t(row[13]), uint8_t(row[14])});
    }
  } else {
    EXPECT_EQ(ply.format, "ascii");
    for (size_t i = 0; i < ply.vertices; ++i) {
      Eigen::Vector3f p;
      int r = -1, g = -1, b = -1;
      header >> p.x() >> p.y() >> p.z() >> r >> g >> b;
      ply.cloud.points.push_back(p);
      ply.cloud.colours.push_back({uint8_t(r), uint8_t(g), uint8_t(b)});
    }
    EXPECT_TRUE(header) << "fewer vertex rows than the header says";
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
