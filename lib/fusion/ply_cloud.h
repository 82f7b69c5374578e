#pragma once
// Coloured point clouds and triangle meshes as PLY files, read and written by hand
// (ply_reader.cpp, ply_writer.cpp), so callers see plain Eigen types.
// Written: the header every reader takes (Open3D, CloudCompare, MeshLab, PCL):
//   ply / format binary_little_endian 1.0 (or ascii 1.0) / element vertex N /
//   property float x, y, z / [property float nx, ny, nz] / property uchar red, green, blue /
//   [element face M / property list uchar int vertex_indices] / end_header
// then N vertices (15 bytes each in binary, 27 with normals) and M triangles. ASCII files
// carry the shortest text that reads back as the same float.
// Read: ascii and binary of either byte order; x, y, z of any scalar type; colours as uchar,
// ushort or float 0..1 (also diffuse_red, ...); normals nx, ny, nz; faces as lists of vertex
// indices, polygons fanned into triangles; other properties and elements skipped.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace slamkit {

using Rgb8 = std::array<uint8_t, 3>;  // red, green, blue

struct PlyCloud {
  std::vector<Eigen::Vector3f> points;
  std::vector<Rgb8> colours;             // one per point
  std::vector<Eigen::Vector3f> normals;  // one per point, or none
  // Faces as vertex index triples (a mesh); none for a point cloud.
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Writes to a temporary file in the same folder (created if missing) and renames it into
// place, so a reader never sees half a file. Throws InputError naming the path when the
// folder or the file cannot be written, when the cloud is empty, when colours (or normals,
// if any) are not one per point, or when a triangle refers to a vertex the cloud lacks.
void write_ply_cloud(const std::filesystem::path& path, const PlyCloud& cloud, bool binary = true);

// Throws InputError naming the path, the reason and, in the header or an ASCII body, the line
// when the file is missing or not a PLY file slamkit can read in full: values are never made
// up. Colours are 0 when the file has none; normals are empty when it has none.
PlyCloud read_ply_cloud(const std::filesystem::path& path);
std::vector<Eigen::Vector3f> read_ply_points(const std::filesystem::path& path);

// The temporary name write_ply_cloud (and fuse_map) write before renaming: "<name>.tmp" in
// the same folder, so the rename never crosses file systems.
std::filesystem::path temporary_path(const std::filesystem::path& path);

}  // namespace slamkit
